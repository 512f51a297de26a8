#include "codegen/routines.hpp"

#include "diag/diagnostics.hpp"

#include <string>

namespace yamsc::codegen {

namespace {

using ir::Pass;
using F = ArgumentForm;
using R = RoutineId;

const std::array<RoutineRow, routine_count> table{{
    {R::rhs,
     "rhs",
     "x' = [q', M^-1 F] for x = [q, q']",
     F::t_x_u_p,
     {"xdot"},
     "yamsc_rhs",
     "YAMSC_EXPORT_RHS",
     false,
     true,
     {}},
    {R::rhs_jacobian,
     "rhs_jacobian",
     "d(rhs)/dx, 2nq x 2nq, row-major",
     F::t_x_u_p,
     {"J"},
     "yamsc_rhs_jacobian",
     "YAMSC_EXPORT_RHS_JACOBIAN",
     true,
     true,
     {Pass::derive_jacobians}},
    {R::mass_matrix,
     "mass_matrix",
     "M(q) of M q'' = F (symmetric, row-major)",
     F::t_q_u_p,
     {"M"},
     "yamsc_mass_matrix",
     "YAMSC_EXPORT_MASS_MATRIX",
     false,
     false,
     {}},
    {R::forcing,
     "forcing",
     "F(q, q', u, t) of M q'' = F",
     F::t_q_qd_u_p,
     {"F"},
     "yamsc_forcing",
     "YAMSC_EXPORT_FORCING",
     false,
     true,
     {}},
    {R::jacobians,
     "jacobians",
     "dF/dq, dF/dq', dF/du (nq x nq, nq x nq, nq x nu)",
     F::t_q_qd_u_p,
     {"dF_dq", "dF_dqd", "dF_du"},
     "yamsc_jacobians",
     "YAMSC_EXPORT_JACOBIANS",
     true,
     true,
     {Pass::derive_jacobians}},
    {R::outputs,
     "outputs",
     "the model's outputs y(q, q', u, t)",
     F::t_q_qd_u_p,
     {"y"},
     "yamsc_outputs",
     "YAMSC_EXPORT_OUTPUTS",
     false,
     true,
     {}},
    {R::outputs_from_qdd,
     "outputs_from_qdd",
     "the outputs y(q, q', q'', u, t) at the given q''; outputs passes the q'' of rhs",
     F::t_q_qd_qdd_u_p,
     {"y"},
     nullptr,
     nullptr,
     false,
     true,
     {}},
    {R::linear,
     "linear",
     "M0 dq'' + C0 dq' + K0 dq = Q0 du about (q0, q0', u0), with q''0 = M0^-1 F0 (eq. 25)",
     F::point,
     {"M0", "C0", "K0", "Q0"},
     nullptr,
     nullptr,
     true,
     true,
     {Pass::derive_jacobians}},
    {R::state_space,
     "state_space",
     "x' = A x + B u linearized about (q0, q0', u0); A 2nq x 2nq, B 2nq x nu",
     F::point,
     {"A", "B"},
     nullptr,
     nullptr,
     true,
     true,
     {Pass::derive_jacobians}},
    {R::output_matrices,
     "output_matrices",
     "dy = C dx + D du about (q0, q0', u0); C ny x 2nq, D ny x nu",
     F::point,
     {"C", "D"},
     nullptr,
     nullptr,
     true,
     true,
     {Pass::derive_jacobians, Pass::output_jacobians}},
    {R::linear_sensitivities,
     "linear_sensitivities",
     "d(M0, C0, K0, Q0)/dp of linear()",
     F::point,
     {"dM0", "dC0", "dK0", "dQ0"},
     nullptr,
     nullptr,
     true,
     false,
     {Pass::derive_jacobians, Pass::parameter_derivatives}},
    {R::operating_point,
     "operating_point",
     "the model's operating point",
     F::p,
     {"q0", "qd0", "u0"},
     nullptr,
     nullptr,
     false,
     false,
     {}},
    {R::constraints,
     "constraints",
     "the constraint residuals: phi(q, t, u) (nh holonomic rows), r = B q' + c (nc rows)",
     F::t_q_qd_u_p,
     {"phi", "r"},
     "yamsc_constraints",
     "YAMSC_EXPORT_CONSTRAINTS",
     false,
     false,
     {Pass::constraint_derivatives}},
    {R::constraint_matrix,
     "constraint_matrix",
     "B = dr/dq' (nc x nq, row-major; its first nh rows are dphi/dq)",
     F::t_q_u_p,
     {"B"},
     "yamsc_constraint_matrix",
     "YAMSC_EXPORT_CONSTRAINT_MATRIX",
     false,
     false,
     {Pass::constraint_derivatives}},
    {R::constraint_bias,
     "constraint_bias",
     "gamma = dr/dt - B q'' (nc) and dr/dq (nc x nq): B q'' + gamma = 0",
     F::t_q_qd_u_p,
     {"gamma", "dr_dq"},
     "yamsc_constraint_bias",
     "YAMSC_EXPORT_CONSTRAINT_BIAS",
     false,
     false,
     {Pass::constraint_derivatives}},
    {R::constraint_jacobians,
     "constraint_jacobians",
     "d(B^T lambda)/dq (nq x nq), d(B a + gamma)/dq (nc x nq), dgamma/dq' (nc x nq), "
     "d(B^T lambda)/du (nq x nu), d(B a + gamma)/du (nc x nu)",
     F::t_q_qd_u_lambda_a_p,
     {"dBTl_dq", "dacc_dq", "dacc_dqd", "dBTl_du", "dacc_du"},
     "yamsc_constraint_jacobians",
     "YAMSC_EXPORT_CONSTRAINT_JACOBIANS",
     false,
     false,
     {Pass::constraint_derivatives}},
}};

} // namespace

const std::array<RoutineRow, routine_count>& routine_table() {
    return table;
}

const RoutineRow& routine_row(RoutineId id) {
    const RoutineRow& row = table.at(static_cast<std::size_t>(id));
    if (row.id != id) throw diag::InternalError("the routine table is out of order");
    return row;
}

std::optional<RoutineId> routine_named(std::string_view name) {
    for (const RoutineRow& row : table)
        if (name == row.name) return row.id;
    return std::nullopt;
}

RoutineSet abi_routines() {
    RoutineSet set;
    for (const RoutineRow& row : table)
        if (row.abi_symbol) set.insert(row.id);
    return set;
}

RoutineSet constraint_routines() {
    return {R::constraints, R::constraint_matrix, R::constraint_bias, R::constraint_jacobians};
}

std::string routine_names(RoutineSet set) {
    std::string out;
    set.for_each(
        [&](RoutineId id) { out += (out.empty() ? "" : ", ") + std::string(routine_name(id)); });
    return out;
}

} // namespace yamsc::codegen
