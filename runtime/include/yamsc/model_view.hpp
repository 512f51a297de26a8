#pragma once
// How the runtime sees a model: sizes, names, and the generated functions with
// the parameters already bound. The runtime never parses anything and never
// depends on a particular model: a view is made either from a generated C++
// model type at compile time (from_generated) or from a model compiled on the
// fly into a shared library (load_shared_model in dynamic_model.hpp).
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace yamsc::runtime {

/// Functions a model was compiled without are empty (`yamsc sim` compiles only
/// what it calls); users test them before calling (the integrators fall back
/// to finite differences without rhs_jacobian).
struct ModelView {
    int nq = 0, nu = 0, ny = 0;
    std::vector<std::string> dof_names, input_names, output_names;

    // x = [q, q'] (2 nq), xdot = [q', q''].
    std::function<void(double t, const double* x, const double* u, double* xdot)> rhs;
    // Row-major 2nq x 2nq Jacobian of rhs with respect to x (exact, generated).
    std::function<void(double t, const double* x, const double* u, double* J)> rhs_jacobian;
    // M may depend on t and u when joints follow prescribed motion.
    std::function<void(double t, const double* q, const double* u, double* M)> mass_matrix;
    std::function<void(double t, const double* q, const double* qd, const double* u, double* F)>
        forcing;
    std::function<void(double t, const double* q, const double* qd, const double* u, double* dF_dq,
                       double* dF_dqd, double* dF_du)>
        jacobians;
    std::function<void(double t, const double* q, const double* qd, const double* u, double* y)>
        outputs;
    // The outputs given q'' = the q'' part of rhs(t, [q, q'], u): then equal
    // to outputs(t, q, q', u) to the last bit, without outputs' own solve of
    // M q'' = F. The fixed-step simulations use it where the integrator has
    // evaluated rhs at the stored point anyway. Optional (empty: they call
    // outputs); a view whose rhs is replaced must replace or clear it.
    std::function<void(double t, const double* q, const double* qd, const double* qdd,
                       const double* u, double* y)>
        outputs_from_qdd;

    // First-order states of load blocks closed around the model (load_block.hpp),
    // after q and q' in x = [q, q', z]. The functions given q and q' apart read
    // them after q' (at qd + nq), as the integrators pass x and x + nq; a view
    // with such states has no forcing or jacobians (it is not second order).
    int nz = 0;
    std::vector<std::string> block_state_names; // nz names
    std::vector<double> block_initial_states;   // nz values

    // Discrete states of load blocks (LoadBlock::update_discrete_states): called
    // once per accepted step from (t, x, u) to (t_next, x_next, u_next), after the
    // integrator has computed x_next and before anything is evaluated at t_next.
    // Empty when no block has discrete states.
    std::function<void(double t, const double* x, const double* u, double t_next,
                       const double* x_next, const double* u_next)>
        update_discrete;
    // Back to the discrete states of a run's start (LoadBlock::reset_discrete_states);
    // set with update_discrete.
    std::function<void()> reset_discrete;

    // Constraints (docs/constraints.md): nc velocity rows r = B(q, t, u) q' + c = 0, the
    // first nh of them holonomic, Phi(q, t, u) = 0 (their rows of B are dPhi/dq). The
    // equations of motion are then M q'' = F + B^T lambda and B q'' + gamma = 0, with
    // gamma = dr/dt - B q''. A view without constraints has nh = nc = 0 and empty functions.
    int nh = 0, nc = 0;
    std::vector<std::string> constraint_names;   // nc, one per row ("closing.x")
    std::vector<int> constraint_dependent;       // nc: the DOF the model names dependent, or -1
    std::vector<std::string> constraint_sources; // nc: "file:line:col" of each row's declaration
    // phi (nh) and r (nc) at (t, q, q', u).
    std::function<void(double t, const double* q, const double* qd, const double* u, double* phi,
                       double* r)>
        constraint_residuals;
    // B, nc x nq row-major.
    std::function<void(double t, const double* q, const double* u, double* B)> constraint_matrix;
    // gamma (nc) and dr/dq (nc x nq row-major).
    std::function<void(double t, const double* q, const double* qd, const double* u, double* gamma,
                       double* dr_dq)>
        constraint_bias;
    // Given lambda (nc) and a (nq): d(B^T lambda)/dq (nq x nq), d(B a + gamma)/dq (nc x nq),
    // dgamma/dq' (nc x nq), d(B^T lambda)/du (nq x nu), d(B a + gamma)/du (nc x nu).
    std::function<void(double t, const double* q, const double* qd, const double* u,
                       const double* lambda, const double* a, double* dBTl_dq, double* dacc_dq,
                       double* dacc_dqd, double* dBTl_du, double* dacc_du)>
        constraint_jacobians;
    // d(M(q, t, u) a)/dq at a given a (nq x nq row-major): the term the constrained
    // rhs_jacobian needs at the constrained q'' (optional: without it the runtime
    // takes central differences of mass_matrix).
    std::function<void(double t, const double* q, const double* a, const double* u, double* dMa_dq)>
        mass_action_jacobian;

    // Called by the integrators after each accepted step at its end (before
    // update_discrete, which then sees the projected state): moves x in place
    // back onto the constraints (q onto Phi = 0, q' onto r = 0; constraints.hpp).
    // Empty without constraints.
    std::function<void(double t, double* x, const double* u)> project;

    int nx() const { return 2 * nq + nz; }
};

namespace detail {
// Whether a generated Model has outputs_from_qdd (older or hand-written ones may not).
template <class Model, class = void> struct has_outputs_from_qdd : std::false_type {};
template <class Model>
struct has_outputs_from_qdd<Model, std::void_t<decltype(&Model::outputs_from_qdd)>>
    : std::true_type {};
// A model with constraints has no generated rhs_jacobian (docs/generated-api.md).
template <class Model, class = void> struct has_rhs_jacobian : std::false_type {};
template <class Model>
struct has_rhs_jacobian<Model, std::void_t<decltype(&Model::rhs_jacobian)>> : std::true_type {};
template <class Model, class = void> struct has_constraints : std::false_type {};
template <class Model>
struct has_constraints<Model, std::void_t<decltype(Model::nc)>> : std::true_type {};

// The constraint rows and routines of a generated model with constraints.
template <class Model> void add_constraints(ModelView& v, const typename Model::Params& p) {
    v.nh = Model::nh;
    v.nc = Model::nc;
    for (int i = 0; i < Model::nc; ++i) {
        v.constraint_names.emplace_back(Model::constraint_names[i]);
        v.constraint_dependent.push_back(Model::constraint_dependent[i]);
        v.constraint_sources.emplace_back(Model::constraint_sources[i]);
    }
    v.constraint_residuals = [p](double t, const double* q, const double* qd, const double* u,
                                 double* phi,
                                 double* r) { Model::constraints(t, q, qd, u, p, phi, r); };
    v.constraint_matrix = [p](double t, const double* q, const double* u, double* B) {
        Model::constraint_matrix(t, q, u, p, B);
    };
    v.constraint_bias = [p](double t, const double* q, const double* qd, const double* u,
                            double* gamma, double* dr_dq) {
        Model::constraint_bias(t, q, qd, u, p, gamma, dr_dq);
    };
    v.constraint_jacobians = [p](double t, const double* q, const double* qd, const double* u,
                                 const double* lambda, const double* a, double* dBTl_dq,
                                 double* dacc_dq, double* dacc_dqd, double* dBTl_du,
                                 double* dacc_du) {
        Model::constraint_jacobians(t, q, qd, u, lambda, a, p, dBTl_dq, dacc_dq, dacc_dqd, dBTl_du,
                                    dacc_du);
    };
}
} // namespace detail

/// A view of a generated C++ model. `Model` is the `<namespace>::Model` bundle the
/// C++ emitter writes; the parameters are copied into the view.
template <class Model> ModelView from_generated(const typename Model::Params& params) {
    ModelView v;
    v.nq = Model::nq;
    v.nu = Model::nu;
    v.ny = Model::ny;
    for (int i = 0; i < Model::nq; ++i) v.dof_names.emplace_back(Model::dof_names[i]);
    for (int i = 0; i < Model::nu; ++i) v.input_names.emplace_back(Model::input_names[i]);
    for (int i = 0; i < Model::ny; ++i) v.output_names.emplace_back(Model::output_names[i]);
    const typename Model::Params p = params;
    v.rhs = [p](double t, const double* x, const double* u, double* xdot) {
        Model::rhs(t, x, u, p, xdot);
    };
    if constexpr (detail::has_rhs_jacobian<Model>::value)
        v.rhs_jacobian = [p](double t, const double* x, const double* u, double* J) {
            Model::rhs_jacobian(t, x, u, p, J);
        };
    v.mass_matrix = [p](double t, const double* q, const double* u, double* M) {
        Model::mass_matrix(t, q, u, p, M);
    };
    v.forcing = [p](double t, const double* q, const double* qd, const double* u, double* F) {
        Model::forcing(t, q, qd, u, p, F);
    };
    v.jacobians = [p](double t, const double* q, const double* qd, const double* u, double* a,
                      double* b, double* c) { Model::jacobians(t, q, qd, u, p, a, b, c); };
    v.outputs = [p](double t, const double* q, const double* qd, const double* u, double* y) {
        Model::outputs(t, q, qd, u, p, y);
    };
    if constexpr (detail::has_outputs_from_qdd<Model>::value)
        v.outputs_from_qdd = [p](double t, const double* q, const double* qd, const double* qdd,
                                 const double* u,
                                 double* y) { Model::outputs_from_qdd(t, q, qd, qdd, u, p, y); };
    if constexpr (detail::has_constraints<Model>::value) detail::add_constraints<Model>(v, p);
    return v;
}

} // namespace yamsc::runtime
