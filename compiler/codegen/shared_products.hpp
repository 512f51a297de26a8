#pragma once
// Products that share two factors compute the pair once. The IR keeps products
// flat (x*y*z is one node with three factors), so hash-consing cannot see that
// x*y*z and x*y*w both contain x*y; in Kane's equations such pairs are many (a
// length times a sine times a cosine in every entry a rotation touches). Pairs
// are taken greedily, the most shared first, until no pair is shared, the way
// common-subexpression passes for n-ary products do.
#include "codegen/module.hpp"

#include <vector>

namespace yamsc::codegen {

/// Rewrites the products among `exprs` (a routine's expressions, operands
/// first) to share their common pairs of factors (of exponent 1). New products
/// are inserted before their first user; every index into `exprs` (operands,
/// the steps' assignments, `step_of_expr`) is updated. `step_of_expr[i]` is the
/// first step that needs expression i.
void share_factor_pairs(std::vector<Expr>& exprs, std::vector<int>& step_of_expr,
                        std::vector<Step>& steps);

} // namespace yamsc::codegen
