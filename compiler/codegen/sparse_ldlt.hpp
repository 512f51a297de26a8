#pragma once
// The symbolic LDL^T of the mass matrix: which entries of M are zero in every
// state (their IR node is the number 0), an elimination order that keeps L
// sparse (minimum degree), the fill-in it causes, and whether generated code
// gets the factorisation as straight-line code for this pattern
// (codegen/ldlt_text.hpp) or calls the generic loops (helpers/ldlt.inc).
//
// Straight-line code skips the structural zeros and has no loop overhead: for
// the 16-DOF NREL 5-MW turbine (blade i does not couple with blade j), factor
// and solve take 0.28 us instead of 0.74 us (docs/benchmarks.md).
#include "ir/graph.hpp"

#include <vector>

namespace yamsc::codegen {

/// pattern[i][j] for j <= i: whether M(i, j) may be nonzero (the lower triangle).
using LowerPattern = std::vector<std::vector<bool>>;

struct LdltPlan {
    int n = 0;
    LowerPattern pattern; // of M, in its own order
    /// order[k]: the row and column of M eliminated k-th. L is that of the
    /// permuted matrix P M P^T, whose row k is row order[k] of M.
    std::vector<int> order;
    /// below[k]: the permuted rows i > k where column k of L may be nonzero,
    /// ascending (the structural nonzeros of M and the fill-in).
    std::vector<std::vector<int>> below;
    int structural_zeros = 0; // in the lower triangle of M, diagonal excluded
    int fill_in = 0;          // entries of L that are zero in M
    /// The factorisation's multiply-subtract updates (terms L(i,k) W(j,k)).
    long updates = 0;
    /// Printed as straight-line code (updates <= straight_line_max_updates);
    /// otherwise generated code calls the generic loops.
    bool straight_line = false;

    /// Whether L(i, j), i > j in permuted indices, may be nonzero.
    bool nonzero(int i, int j) const;
    /// Whether the permuted entry (i, j) is one of M's structural nonzeros
    /// (if not, but nonzero(i, j), it is fill-in).
    bool nonzero_in_m(int i, int j) const;
};

/// Straight-line code up to this many updates. A dense M of n DOFs has
/// (n^3 - n) / 6: 2300 at 24 DOFs, the largest the unrolled form derives (from
/// 25 the driver takes the tangent form), 10 660 at 40 and 85 320 at 80 DOFs,
/// where one function of that many statements would cost the C++ compiler more
/// than the loops cost at run time (and the loops' overhead matters less).
inline constexpr long straight_line_max_updates = 2500;

/// The lower triangle of M: false where the entry's node is the number 0.
LowerPattern mass_pattern(const ir::Graph& graph, const std::vector<std::vector<ir::NodeId>>& M);
/// Every entry may be nonzero (the tangent form computes M by columns).
LowerPattern dense_pattern(int n);

/// Minimum degree: repeatedly eliminates the row whose remaining pattern is
/// smallest, ties broken by the smaller original pattern (coupled to fewer
/// rows: the leaves of a structure, e.g. each blade's modes before the
/// hub's), then by the lower index, so the order depends on the pattern only.
/// The diagonal is taken as nonzero (M is positive definite).
LdltPlan plan_ldlt(const LowerPattern& pattern);

} // namespace yamsc::codegen
