#pragma once
// Products that share two factors compute the pair once, and so do sums that
// share two terms in the same ratio. The IR keeps sums and products flat
// (x*y*z is one node with three factors), so hash-consing cannot see that
// x*y*z and x*y*w both contain x*y, or that a + 2b + c and 3a + 6b + d both
// contain a + 2b; in Kane's equations such pairs are many (a length times a
// sine times a cosine in every entry a rotation touches, the same two
// velocity terms in every body's loads). Pairs are taken greedily, the most
// shared first, until no pair is shared (products first, then sums), the way
// common-subexpression passes for n-ary operations do. A sum's pair needs an
// exact ratio of its weights, so that only the order of rounding changes.
#include "codegen/module.hpp"

#include <vector>

namespace yamsc::codegen {

/// Rewrites the products and sums among `exprs` (a routine's expressions,
/// operands first) to share their common pairs of factors (of exponent 1) and
/// of terms. New nodes are inserted before their first user; every index into `exprs` (operands,
/// the steps' assignments, `step_of_expr`) is updated. `step_of_expr[i]` is the
/// first step that needs expression i.
void share_pairs(std::vector<Expr>& exprs, std::vector<int>& step_of_expr,
                 std::vector<Step>& steps);

} // namespace yamsc::codegen
