#pragma once
// The routines of a model with constraints (docs/generated-api.md, Constraints):
// its rows (constraints), B (constraint_matrix), gamma and dr/dq
// (constraint_bias), the Jacobians the runtime's constrained view needs
// (constraint_jacobians), and the constrained rhs: M q'' = F + B^T lambda,
// B q'' + gamma = 0, solved through the Schur complement B M^-1 B^T.
#include "codegen/module.hpp"

#include <vector>

namespace yamsc::codegen {

/// Appends constraints, constraint_matrix, constraint_bias and constraint_jacobians.
void add_constraint_routines(Graph& g, const ir::System& s, const Options& options,
                             std::vector<Routine>& routines);

/// rhs(t, x, u, p, xdot) of the constrained motion: q''u = M^-1 F, Y = M^-1 B^T,
/// (B Y) lambda = -(gamma + B q''u), q'' = q''u + Y lambda (the generic LDL^T
/// helper factors B Y, symmetric positive definite while the rows are independent).
Routine constrained_rhs_routine(Graph& g, const ir::System& s, const Options& options);

} // namespace yamsc::codegen
