#pragma once
// The passes: IR to IR. Each adds rows of derivatives to an ir::System, built
// by forward mode (passes/forward.hpp) in the System's own graph, so every
// derivative shares the nodes of the equations and of the other derivatives.
// What each adds and needs is a row of passes/pass_order.hpp, checked when it
// runs; passes/pipeline.hpp runs them in order for the front end.
#include "ir/system.hpp"

#include <cstddef>
#include <vector>

namespace yamsc::passes {

/// One `approx` group: M and F replaced by their Taylor polynomials about 0 in
/// `group` (variables: q, u or p), truncated at total order `order`
/// (passes/taylor.hpp). The first call keeps the rows as derived in exact_M and
/// exact_F; the outputs and M a stay exact. Run before the derivatives. Throws
/// NotExpandable (taylor.hpp) for what has no expansion.
void approximate(ir::System& s, const std::vector<ir::SymbolRef>& group, int order);

/// dF_dq, dF_dqd, dF_du and dMa_dq (forming M a from M when Kane's method left
/// it empty).
void derive_jacobians(ir::System& s);

/// The tangent form, for models too large for the unrolled Jacobians: dG and
/// dY, one directional derivative of G = F - M a (a held) and of the outputs
/// along the seed symbols [dq, dq', du]. Needs M a.
void derive_tangent(ir::System& s);

/// C = [∂y/∂q, ∂y/∂q'] and D = ∂y/∂u: the linear model's output matrices.
void output_jacobians(ir::System& s);

/// Moves the last outputs, the arguments of the externals (model::with_external_channels
/// appends them), into `s.externals[k].args`; each external's `args` holds how
/// many it takes on entry (placeholders). Drops the operating point's values of the
/// externals' input channels. Run right after lowering.
void separate_externals(ir::System& s);

/// The arguments' derivatives dargs_dq, dargs_dqd, dargs_du of every external.
void external_jacobians(ir::System& s);

/// The derivatives of M, F and the Jacobians with respect to each parameter of
/// `params` (indices into s.params, in that order; sensitivities of the linear
/// model, docs/linearization.md). Needs derive_jacobians.
void parameter_derivatives(ir::System& s, const std::vector<std::size_t>& params);

/// B, ∂r/∂q, γ of the constraint rows and the Jacobians of Bᵀλ and B a + γ
/// (ir::System::B ...; docs/theory.md, Constraint rows). Run whenever the model
/// has constraints.
void constraint_derivatives(ir::System& s);

} // namespace yamsc::passes
