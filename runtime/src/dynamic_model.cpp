#include "yamsc/dynamic_model.hpp"

#include "yamsc/abi_export.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace yamsc::runtime {

// The open library and its resolved entry points. Views share it, so the
// library is closed only when the last of them is gone.
struct SharedModel::Library {
    void* handle = nullptr;
    yamsc_sizes_fn sizes = nullptr;
    yamsc_name_fn name = nullptr;
    yamsc_default_params_fn default_params = nullptr;
    yamsc_rhs_fn rhs = nullptr;
    yamsc_rhs_jacobian_fn rhs_jacobian = nullptr;
    yamsc_mass_matrix_fn mass_matrix = nullptr;
    yamsc_forcing_fn forcing = nullptr;
    yamsc_jacobians_fn jacobians = nullptr;
    yamsc_outputs_fn outputs = nullptr;
    // Optional: the parameters converted once per view (abi_export.hpp).
    yamsc_params_bytes_fn params_bytes = nullptr;
    yamsc_params_bind_fn params_bind = nullptr;
    yamsc_rhs_bound_fn rhs_bound = nullptr;
    yamsc_rhs_jacobian_bound_fn rhs_jacobian_bound = nullptr;
    yamsc_outputs_bound_fn outputs_bound = nullptr;
    // Optional: the outputs given the q'' of rhs (abi_export.hpp).
    yamsc_outputs_from_qdd_fn outputs_from_qdd = nullptr;
    yamsc_outputs_from_qdd_bound_fn outputs_from_qdd_bound = nullptr;
    // Optional: the constraint rows (abi_export.hpp).
    yamsc_constraints_fn constraints = nullptr;
    yamsc_constraint_matrix_fn constraint_matrix = nullptr;
    yamsc_constraint_bias_fn constraint_bias = nullptr;
    yamsc_constraint_jacobians_fn constraint_jacobians = nullptr;

    Library() = default;
    Library(const Library&) = delete;
    Library& operator=(const Library&) = delete;
    ~Library() {
        if (handle) dlclose(handle);
    }
};

namespace {

template <class Function>
Function resolve(void* handle, const char* symbol, const std::string& path) {
    dlerror(); // clear a stale error
    void* address = dlsym(handle, symbol);
    if (!address) {
        const char* why = dlerror();
        throw SharedModelError("'" + path + "' is not a yamsc model: symbol " + symbol +
                               " is missing" + (why ? std::string(" (") + why + ")" : ""));
    }
    // POSIX guarantees that object pointers from dlsym convert to function pointers.
    return reinterpret_cast<Function>(address);
}

/// A routine the library may leave out (abi_export.hpp): null when absent.
template <class Function> Function optional_routine(void* handle, const char* symbol) {
    dlerror();
    return reinterpret_cast<Function>(dlsym(handle, symbol));
}

std::vector<std::string> names_of(yamsc_name_fn name, int kind, int count,
                                  const std::string& path) {
    std::vector<std::string> names;
    for (int i = 0; i < count; ++i) {
        const char* n = name(kind, i);
        if (!n)
            throw SharedModelError("'" + path + "' has no name for entry " + std::to_string(i) +
                                   " of kind " + std::to_string(kind));
        names.emplace_back(n);
    }
    return names;
}

} // namespace

SharedModel::SharedModel(const std::string& path) : path_(path) {
    auto library = std::make_shared<Library>();
    // RTLD_LOCAL: several models export the same symbol names and must not see
    // each other's.
    library->handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library->handle) {
        const char* why = dlerror();
        throw SharedModelError("cannot load model library '" + path +
                               "': " + (why ? why : "unknown error"));
    }
    void* h = library->handle;
    const auto version = resolve<yamsc_abi_version_fn>(h, "yamsc_abi_version", path)();
    if (version != YAMSC_ABI_VERSION)
        throw SharedModelError("'" + path + "' was built for model ABI version " +
                               std::to_string(version) + ", this runtime needs version " +
                               std::to_string(YAMSC_ABI_VERSION) + "; recompile the model");
    library->sizes = resolve<yamsc_sizes_fn>(h, "yamsc_sizes", path);
    library->name = resolve<yamsc_name_fn>(h, "yamsc_name", path);
    library->default_params = resolve<yamsc_default_params_fn>(h, "yamsc_default_params", path);
    library->rhs = optional_routine<yamsc_rhs_fn>(h, "yamsc_rhs");
    library->rhs_jacobian = optional_routine<yamsc_rhs_jacobian_fn>(h, "yamsc_rhs_jacobian");
    library->mass_matrix = optional_routine<yamsc_mass_matrix_fn>(h, "yamsc_mass_matrix");
    library->forcing = optional_routine<yamsc_forcing_fn>(h, "yamsc_forcing");
    library->jacobians = optional_routine<yamsc_jacobians_fn>(h, "yamsc_jacobians");
    library->outputs = optional_routine<yamsc_outputs_fn>(h, "yamsc_outputs");
    library->params_bytes = optional_routine<yamsc_params_bytes_fn>(h, "yamsc_params_bytes");
    library->params_bind = optional_routine<yamsc_params_bind_fn>(h, "yamsc_params_bind");
    if (library->params_bytes && library->params_bind) {
        library->rhs_bound = optional_routine<yamsc_rhs_bound_fn>(h, "yamsc_rhs_bound");
        library->rhs_jacobian_bound =
            optional_routine<yamsc_rhs_jacobian_bound_fn>(h, "yamsc_rhs_jacobian_bound");
        library->outputs_bound = optional_routine<yamsc_outputs_bound_fn>(h, "yamsc_outputs_bound");
    }
    if (library->outputs)
        if (const auto routines = optional_routine<yamsc_outputs_from_qdd_routines_fn>(
                h, "yamsc_outputs_from_qdd_routines"))
            routines(&library->outputs_from_qdd, &library->outputs_from_qdd_bound);
    if (!library->rhs)
        throw SharedModelError("'" + path + "' is not a yamsc model: symbol yamsc_rhs is missing");

    library->sizes(&nq_, &nu_, &np_, &ny_);
    if (nq_ < 0 || nu_ < 0 || np_ < 0 || ny_ < 0)
        throw SharedModelError("'" + path + "' reports negative sizes");
    dof_names_ = names_of(library->name, yamsc_name_dof, nq_, path);
    input_names_ = names_of(library->name, yamsc_name_input, nu_, path);
    param_names_ = names_of(library->name, yamsc_name_param, np_, path);
    output_names_ = names_of(library->name, yamsc_name_output, ny_, path);
    read_constraints(*library, h);
    library_ = std::move(library);
}

void SharedModel::read_constraints(Library& library, void* h) {
    const auto sizes = optional_routine<yamsc_constraint_sizes_fn>(h, "yamsc_constraint_sizes");
    const auto row = optional_routine<yamsc_constraint_row_fn>(h, "yamsc_constraint_row");
    if (!sizes || !row) return;
    sizes(&nh_, &nc_);
    if (nh_ < 0 || nc_ < nh_)
        throw SharedModelError("'" + path_ + "' reports bad constraint sizes");
    for (int i = 0; i < nc_; ++i) {
        int dependent = -1;
        const char* source = nullptr;
        const char* name = row(i, &dependent, &source);
        if (!name || !source)
            throw SharedModelError("'" + path_ + "' has no name for constraint row " +
                                   std::to_string(i));
        constraint_names_.emplace_back(name);
        constraint_sources_.emplace_back(source);
        constraint_dependent_.push_back(dependent);
    }
    library.constraints = optional_routine<yamsc_constraints_fn>(h, "yamsc_constraints");
    library.constraint_matrix =
        optional_routine<yamsc_constraint_matrix_fn>(h, "yamsc_constraint_matrix");
    library.constraint_bias =
        optional_routine<yamsc_constraint_bias_fn>(h, "yamsc_constraint_bias");
    library.constraint_jacobians =
        optional_routine<yamsc_constraint_jacobians_fn>(h, "yamsc_constraint_jacobians");
}

std::vector<double> SharedModel::default_params() const {
    // One spare slot: a model without parameters may still write nothing to a
    // non-null pointer.
    std::vector<double> p(static_cast<std::size_t>(np_) + 1);
    library_->default_params(p.data());
    p.pop_back();
    return p;
}

std::vector<std::string> SharedModel::routines() const {
    const std::pair<const char*, bool> all[] = {
        {"rhs", library_->rhs != nullptr},
        {"rhs_jacobian", library_->rhs_jacobian != nullptr},
        {"mass_matrix", library_->mass_matrix != nullptr},
        {"forcing", library_->forcing != nullptr},
        {"jacobians", library_->jacobians != nullptr},
        {"outputs", library_->outputs != nullptr},
        {"constraints", library_->constraints != nullptr},
        {"constraint_matrix", library_->constraint_matrix != nullptr},
        {"constraint_bias", library_->constraint_bias != nullptr},
        {"constraint_jacobians", library_->constraint_jacobians != nullptr}};
    std::vector<std::string> present;
    for (const auto& [name, here] : all)
        if (here) present.emplace_back(name);
    return present;
}

int SharedModel::param_index(const std::string& name) const {
    for (std::size_t i = 0; i < param_names_.size(); ++i)
        if (param_names_[i] == name) return static_cast<int>(i);
    return -1;
}

ModelView SharedModel::view(std::vector<double> params) const {
    if (params.size() != static_cast<std::size_t>(np_))
        throw std::invalid_argument("got " + std::to_string(params.size()) +
                                    " parameter values, the model has " + std::to_string(np_));
    for (std::size_t i = 0; i < params.size(); ++i)
        if (std::isnan(params[i]))
            throw std::invalid_argument("parameter '" + param_names_[i] +
                                        "' has no value (no default and not set)");

    ModelView v;
    v.nq = nq_;
    v.nu = nu_;
    v.ny = ny_;
    v.dof_names = dof_names_;
    v.input_names = input_names_;
    v.output_names = output_names_;
    // Each function holds the library and its own copy of the parameters.
    const auto lib = library_;
    const auto p = std::make_shared<const std::vector<double>>(std::move(params));
    // The model's Params built once from p, for the routines that take them bound.
    std::shared_ptr<const std::vector<std::max_align_t>> bound;
    if (lib->params_bytes && lib->params_bind) {
        const auto bytes = static_cast<std::size_t>(std::max(lib->params_bytes(), 1));
        auto storage = std::make_shared<std::vector<std::max_align_t>>(
            (bytes + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t));
        lib->params_bind(p->data(), storage->data());
        bound = std::move(storage);
    }
    if (bound && lib->rhs_bound)
        v.rhs = [lib, bound](double t, const double* x, const double* u, double* xdot) {
            lib->rhs_bound(t, x, u, bound->data(), xdot);
        };
    else
        v.rhs = [lib, p](double t, const double* x, const double* u, double* xdot) {
            lib->rhs(t, x, u, p->data(), xdot);
        };
    // Routines the library was compiled without stay empty (ModelView's contract).
    if (bound && lib->rhs_jacobian_bound)
        v.rhs_jacobian = [lib, bound](double t, const double* x, const double* u, double* J) {
            lib->rhs_jacobian_bound(t, x, u, bound->data(), J);
        };
    else if (lib->rhs_jacobian)
        v.rhs_jacobian = [lib, p](double t, const double* x, const double* u, double* J) {
            lib->rhs_jacobian(t, x, u, p->data(), J);
        };
    if (lib->mass_matrix)
        v.mass_matrix = [lib, p](double t, const double* q, const double* u, double* M) {
            lib->mass_matrix(t, q, u, p->data(), M);
        };
    if (lib->forcing)
        v.forcing = [lib, p](double t, const double* q, const double* qd, const double* u,
                             double* F) { lib->forcing(t, q, qd, u, p->data(), F); };
    if (lib->jacobians)
        v.jacobians = [lib, p](double t, const double* q, const double* qd, const double* u,
                               double* dF_dq, double* dF_dqd, double* dF_du) {
            lib->jacobians(t, q, qd, u, p->data(), dF_dq, dF_dqd, dF_du);
        };
    if (bound && lib->outputs_bound)
        v.outputs = [lib, bound](double t, const double* q, const double* qd, const double* u,
                                 double* y) { lib->outputs_bound(t, q, qd, u, bound->data(), y); };
    else if (lib->outputs)
        v.outputs = [lib, p](double t, const double* q, const double* qd, const double* u,
                             double* y) { lib->outputs(t, q, qd, u, p->data(), y); };
    // Left empty without it: the simulations then call outputs.
    if (bound && lib->outputs_from_qdd_bound)
        v.outputs_from_qdd = [lib, bound](double t, const double* q, const double* qd,
                                          const double* qdd, const double* u, double* y) {
            lib->outputs_from_qdd_bound(t, q, qd, qdd, u, bound->data(), y);
        };
    else if (lib->outputs_from_qdd)
        v.outputs_from_qdd = [lib, p](double t, const double* q, const double* qd,
                                      const double* qdd, const double* u, double* y) {
            lib->outputs_from_qdd(t, q, qd, qdd, u, p->data(), y);
        };
    v.nh = nh_;
    v.nc = nc_;
    v.constraint_names = constraint_names_;
    v.constraint_dependent = constraint_dependent_;
    v.constraint_sources = constraint_sources_;
    if (lib->constraints)
        v.constraint_residuals = [lib, p](double t, const double* q, const double* qd,
                                          const double* u, double* phi, double* r) {
            lib->constraints(t, q, qd, u, p->data(), phi, r);
        };
    if (lib->constraint_matrix)
        v.constraint_matrix = [lib, p](double t, const double* q, const double* u, double* B) {
            lib->constraint_matrix(t, q, u, p->data(), B);
        };
    if (lib->constraint_bias)
        v.constraint_bias = [lib, p](double t, const double* q, const double* qd, const double* u,
                                     double* gamma, double* dr_dq) {
            lib->constraint_bias(t, q, qd, u, p->data(), gamma, dr_dq);
        };
    if (lib->constraint_jacobians)
        v.constraint_jacobians = [lib, p](double t, const double* q, const double* qd,
                                          const double* u, const double* lambda, const double* a,
                                          double* dBTl_dq, double* dacc_dq, double* dacc_dqd,
                                          double* dBTl_du, double* dacc_du) {
            lib->constraint_jacobians(t, q, qd, u, lambda, a, p->data(), dBTl_dq, dacc_dq, dacc_dqd,
                                      dBTl_du, dacc_du);
        };
    return v;
}

} // namespace yamsc::runtime
