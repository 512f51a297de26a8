#pragma once
// Kane's method: the checked model -> M(q) q'' = F(q, q', u, t) and outputs.
#include "model/model.hpp"
#include "symbolic/equations.hpp"

namespace yamsc::symbolic {

/// Derives the equations of motion of a checked model (paper eq. 4-10, 21-22).
/// Reports user errors (e.g. loads nonlinear in q'') into `diags` and returns
/// nullopt on error.
std::optional<Equations> derive(const model::Model& m, diag::Diagnostics& diags);

/// Fills the exact Jacobians dF/dq, dF/dq', dF/du and d(M a)/dq.
void derive_jacobians(Equations& eq);

} // namespace yamsc::symbolic
