#pragma once
// Kane's method: the checked model -> M(q) q'' = F(q, q', u, t) and outputs.
#include "model/model.hpp"
#include "symbolic/equations.hpp"

namespace yamsc::symbolic {

/// Derives the equations of motion of a checked model (paper eq. 4-10, 21-22).
/// Reports user errors (e.g. loads nonlinear in q'') into `diags` and returns
/// nullopt on error.
/// With `mass_matrix` false, M is not assembled (eq.M stays empty; M a is):
/// the tangent form, whose cost is O(bodies x DOFs) instead of O(bodies x DOFs²).
std::optional<Equations> derive(const model::Model& m, diag::Diagnostics& diags,
                                bool mass_matrix = true);

} // namespace yamsc::symbolic
