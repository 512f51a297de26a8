#pragma once
// The routine `linear_sensitivities` (docs/linearization.md, "Parameter
// sensitivities"): the exact partial derivatives of the linear model's M0, C0,
// K0 and Q0 with respect to chosen parameters, at an operating point
// (q0, q0', u0) given as arguments, for design optimisation and co-design.
#include "codegen/linear_routines.hpp"
#include "codegen/module.hpp"

#include <vector>

namespace yamsc::codegen {

/// Appends `linear_sensitivities(q0, qd0, u0, p, dM0, dC0, dK0, dQ0)` for
/// options.sensitivity_params (names of s.params, in that order) to `routines`;
/// nothing when the list is empty or the model has no DOF. Block j of dM0, dC0,
/// dK0 (nq x nq each) and of dQ0 (nq x nu) is the derivative with respect to the
/// j-th name, from s.sensitivities (passes::parameter_derivatives). Throws
/// diag::InternalError for a name that is not a parameter or whose derivatives
/// the System lacks.
void add_sensitivity_routine(Graph& graph, const ir::System& s, const LinearSources& in,
                             const Options& options, std::vector<Routine>& routines);

} // namespace yamsc::codegen
