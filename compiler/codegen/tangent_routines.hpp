#pragma once
// The module of equations in the tangent form (ir::System::tangent_form,
// docs/benchmarks.md): two internal routines, `mass_times` (M a) and
// `tangent` (the directional derivative of G = F - M a and of the outputs),
// and the public routines of the unrolled form with the same signatures, whose
// matrices are filled column by column by sweeps over unit directions. The
// code is O(size of F, M a and y) instead of O(nq x that); each matrix costs
// nq calls at run time.
#include "codegen/module.hpp"

namespace yamsc::codegen {

/// mass_matrix, forcing, jacobians, outputs_from_qdd, outputs, rhs, rhs_jacobian and (with
/// options.linear_model) linear, state_space and output_matrices, plus the
/// internal routines they call. `module.model` and `module.options` must be
/// set. Throws diag::InternalError when the equations are not in tangent form.
void add_tangent_routines(Module& module, const ir::System& s);

} // namespace yamsc::codegen
