#ifndef YAMSC_ABI_EXPORT_HPP
#define YAMSC_ABI_EXPORT_HPP
// A C ABI for a generated C++ model, so that `yamsc sim` can compile a model
// into a shared library on the fly and load it with dlopen (dynamic_model.hpp).
//
// This header is self-contained on purpose (standard headers only): its text is
// embedded in the compiler and pasted after the generated source, so it may be
// the main file of a translation unit (hence include guards, not a pragma that
// warns in a main file). Usage, after the generated code in the same unit:
//
//     YAMSC_EXPORT_MODEL(my_model_namespace)
//
// Compile with `-shared -fPIC -fvisibility=hidden`: only the functions below are
// exported, so the model's own symbols can never be interposed by the host.
//
// The routines (rhs, rhs_jacobian, mass_matrix, forcing, jacobians, outputs)
// are optional: YAMSC_EXPORT_MODEL_INFO plus one YAMSC_EXPORT_<ROUTINE> per
// routine the source defines. The loader requires the model information and
// leaves a routine the library lacks empty in its views.
//
// Parameters cross the ABI as a flat array of `np` doubles in declaration
// order (NS::Model::params_to_array / params_from_array). Converting that
// array into the model's Params at every call costs a few per cent of a small
// model's rhs, so the hot routines (rhs, rhs_jacobian, outputs) also come
// bound: yamsc_params_bind converts the array once into yamsc_params_bytes()
// bytes of storage the caller keeps (aligned as max_align_t), and the
// yamsc_*_bound routines take that storage instead of the array. These
// symbols are optional: a loader falls back to the array routines without them.

// Bumped whenever a signature below changes; the loader refuses other versions.
#define YAMSC_ABI_VERSION 1

#if defined(__GNUC__) || defined(__clang__)
#define YAMSC_ABI_VISIBLE __attribute__((visibility("default")))
#else
#define YAMSC_ABI_VISIBLE
#endif

// Function pointer types of the exported symbols, shared by the exporting
// macro and the loader so that the two sides cannot disagree.
extern "C" {
typedef int (*yamsc_abi_version_fn)(void);
typedef void (*yamsc_sizes_fn)(int* nq, int* nu, int* np, int* ny);
typedef const char* (*yamsc_name_fn)(int kind, int i);
typedef void (*yamsc_default_params_fn)(double* p);
typedef void (*yamsc_rhs_fn)(double t, const double* x, const double* u, const double* p,
                             double* xdot);
typedef void (*yamsc_rhs_jacobian_fn)(double t, const double* x, const double* u, const double* p,
                                      double* J);
typedef void (*yamsc_mass_matrix_fn)(double t, const double* q, const double* u, const double* p,
                                     double* M);
typedef void (*yamsc_forcing_fn)(double t, const double* q, const double* qd, const double* u,
                                 const double* p, double* F);
typedef void (*yamsc_jacobians_fn)(double t, const double* q, const double* qd, const double* u,
                                   const double* p, double* dF_dq, double* dF_dqd, double* dF_du);
typedef void (*yamsc_outputs_fn)(double t, const double* q, const double* qd, const double* u,
                                 const double* p, double* y);
typedef int (*yamsc_params_bytes_fn)(void);
typedef void (*yamsc_params_bind_fn)(const double* p, void* params);
typedef void (*yamsc_rhs_bound_fn)(double t, const double* x, const double* u, const void* params,
                                   double* xdot);
typedef void (*yamsc_rhs_jacobian_bound_fn)(double t, const double* x, const double* u,
                                            const void* params, double* J);
typedef void (*yamsc_outputs_bound_fn)(double t, const double* q, const double* qd, const double* u,
                                       const void* params, double* y);
}

// Name kinds of yamsc_name().
enum yamsc_name_kind {
    yamsc_name_dof = 0,
    yamsc_name_input = 1,
    yamsc_name_param = 2,
    yamsc_name_output = 3
};

#include <new>
#include <type_traits>

namespace yamsc_abi_detail {
// Out-of-range requests give a null pointer rather than reading past the
// arrays (which hold max(n, 1) entries).
inline const char* name_at(const char* const* names, int n, int i) {
    return (i >= 0 && i < n) ? names[i] : nullptr;
}
} // namespace yamsc_abi_detail

// The sizes, names and parameters: every library exports these.
#define YAMSC_EXPORT_MODEL_INFO(NS)                                                                \
    extern "C" {                                                                                   \
    YAMSC_ABI_VISIBLE int yamsc_abi_version(void) {                                                \
        return YAMSC_ABI_VERSION;                                                                  \
    }                                                                                              \
    YAMSC_ABI_VISIBLE void yamsc_sizes(int* nq, int* nu, int* np, int* ny) {                       \
        *nq = NS::Model::nq;                                                                       \
        *nu = NS::Model::nu;                                                                       \
        *np = NS::Model::np;                                                                       \
        *ny = NS::Model::ny;                                                                       \
    }                                                                                              \
    YAMSC_ABI_VISIBLE const char* yamsc_name(int kind, int i) {                                    \
        switch (kind) {                                                                            \
        case yamsc_name_dof:                                                                       \
            return yamsc_abi_detail::name_at(NS::Model::dof_names, NS::Model::nq, i);              \
        case yamsc_name_input:                                                                     \
            return yamsc_abi_detail::name_at(NS::Model::input_names, NS::Model::nu, i);            \
        case yamsc_name_param:                                                                     \
            return yamsc_abi_detail::name_at(NS::Model::param_names, NS::Model::np, i);            \
        case yamsc_name_output:                                                                    \
            return yamsc_abi_detail::name_at(NS::Model::output_names, NS::Model::ny, i);           \
        default:                                                                                   \
            return nullptr;                                                                        \
        }                                                                                          \
    }                                                                                              \
    YAMSC_ABI_VISIBLE void yamsc_default_params(double* p) {                                       \
        NS::Model::params_to_array(NS::Model::Params{}, p);                                        \
    }                                                                                              \
    /* Params is plain data: the caller's storage is never destroyed as one. */                    \
    static_assert(std::is_trivially_destructible<NS::Model::Params>::value,                        \
                  "bound parameters need trivially destructible Params");                          \
    YAMSC_ABI_VISIBLE int yamsc_params_bytes(void) {                                               \
        return static_cast<int>(sizeof(NS::Model::Params));                                        \
    }                                                                                              \
    YAMSC_ABI_VISIBLE void yamsc_params_bind(const double* p, void* params) {                      \
        ::new (params) NS::Model::Params(NS::Model::params_from_array(p));                         \
    }                                                                                              \
    }

// One macro per routine: a library compiled for one command (`yamsc sim`
// compiles rhs and outputs) exports only the routines its source defines.
#define YAMSC_EXPORT_RHS(NS)                                                                       \
    extern "C" YAMSC_ABI_VISIBLE void yamsc_rhs(double t, const double* x, const double* u,        \
                                                const double* p, double* xdot) {                   \
        NS::Model::rhs(t, x, u, NS::Model::params_from_array(p), xdot);                            \
    }                                                                                              \
    extern "C" YAMSC_ABI_VISIBLE void yamsc_rhs_bound(double t, const double* x, const double* u,  \
                                                      const void* params, double* xdot) {          \
        NS::Model::rhs(t, x, u, *static_cast<const NS::Model::Params*>(params), xdot);             \
    }
#define YAMSC_EXPORT_RHS_JACOBIAN(NS)                                                              \
    extern "C" YAMSC_ABI_VISIBLE void yamsc_rhs_jacobian(                                          \
        double t, const double* x, const double* u, const double* p, double* J) {                  \
        NS::Model::rhs_jacobian(t, x, u, NS::Model::params_from_array(p), J);                      \
    }                                                                                              \
    extern "C" YAMSC_ABI_VISIBLE void yamsc_rhs_jacobian_bound(                                    \
        double t, const double* x, const double* u, const void* params, double* J) {               \
        NS::Model::rhs_jacobian(t, x, u, *static_cast<const NS::Model::Params*>(params), J);       \
    }
#define YAMSC_EXPORT_MASS_MATRIX(NS)                                                               \
    extern "C" YAMSC_ABI_VISIBLE void yamsc_mass_matrix(                                           \
        double t, const double* q, const double* u, const double* p, double* M) {                  \
        NS::Model::mass_matrix(t, q, u, NS::Model::params_from_array(p), M);                       \
    }
#define YAMSC_EXPORT_FORCING(NS)                                                                   \
    extern "C" YAMSC_ABI_VISIBLE void yamsc_forcing(double t, const double* q, const double* qd,   \
                                                    const double* u, const double* p, double* F) { \
        NS::Model::forcing(t, q, qd, u, NS::Model::params_from_array(p), F);                       \
    }
#define YAMSC_EXPORT_JACOBIANS(NS)                                                                 \
    extern "C" YAMSC_ABI_VISIBLE void yamsc_jacobians(                                             \
        double t, const double* q, const double* qd, const double* u, const double* p,             \
        double* dF_dq, double* dF_dqd, double* dF_du) {                                            \
        NS::Model::jacobians(t, q, qd, u, NS::Model::params_from_array(p), dF_dq, dF_dqd, dF_du);  \
    }
#define YAMSC_EXPORT_OUTPUTS(NS)                                                                   \
    extern "C" YAMSC_ABI_VISIBLE void yamsc_outputs(double t, const double* q, const double* qd,   \
                                                    const double* u, const double* p, double* y) { \
        NS::Model::outputs(t, q, qd, u, NS::Model::params_from_array(p), y);                       \
    }                                                                                              \
    extern "C" YAMSC_ABI_VISIBLE void yamsc_outputs_bound(double t, const double* q,               \
                                                          const double* qd, const double* u,       \
                                                          const void* params, double* y) {         \
        NS::Model::outputs(t, q, qd, u, *static_cast<const NS::Model::Params*>(params), y);        \
    }

// Everything: a model compiled with all its routines (the generated default).
#define YAMSC_EXPORT_MODEL(NS)                                                                     \
    YAMSC_EXPORT_MODEL_INFO(NS)                                                                    \
    YAMSC_EXPORT_RHS(NS)                                                                           \
    YAMSC_EXPORT_RHS_JACOBIAN(NS)                                                                  \
    YAMSC_EXPORT_MASS_MATRIX(NS)                                                                   \
    YAMSC_EXPORT_FORCING(NS)                                                                       \
    YAMSC_EXPORT_JACOBIANS(NS)                                                                     \
    YAMSC_EXPORT_OUTPUTS(NS)

#endif // YAMSC_ABI_EXPORT_HPP
