// Shared pairs (codegen/shared_products.hpp): products that share two factors
// compute the pair once, sums that share two terms in the same ratio compute
// their sum once; the expressions stay in operand-first order with every index
// remapped, the values are unchanged, and what has nothing to share is left
// alone.
#include "codegen/shared_products.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace yamsc::codegen;

namespace {

Expr load(int index) {
    Expr e;
    e.kind = ExprKind::load;
    e.array = "x";
    e.index = index;
    return e;
}

Expr product(double coefficient, std::vector<ExprOperand> factors) {
    Expr e;
    e.kind = ExprKind::mul;
    e.value = coefficient;
    e.operands = std::move(factors);
    return e;
}

Expr sum(std::vector<ExprOperand> terms) {
    Expr e;
    e.kind = ExprKind::add;
    e.operands = std::move(terms);
    return e;
}

/// The values of the expressions with x = (2, 3, 5, 7).
std::vector<double> values(const std::vector<Expr>& exprs) {
    const double x[] = {2, 3, 5, 7};
    std::vector<double> v;
    for (const Expr& e : exprs) {
        double r = e.value;
        for (const ExprOperand& op : e.operands) {
            REQUIRE(op.expr < static_cast<int>(v.size())); // operands first
            const double o = v[static_cast<std::size_t>(op.expr)];
            if (e.kind == ExprKind::mul) r *= std::pow(o, op.weight);
            if (e.kind == ExprKind::add) r += op.weight * o;
        }
        v.push_back(e.kind == ExprKind::load ? x[e.index] : r);
    }
    return v;
}

int multiplications(const std::vector<Expr>& exprs) {
    int n = 0;
    for (const Expr& e : exprs)
        if (e.kind == ExprKind::mul)
            n += static_cast<int>(e.operands.size()) - 1 + (e.value != 1.0 ? 1 : 0);
    return n;
}

} // namespace

TEST_CASE("products sharing two factors compute the pair once") {
    // 0..3: x0..x3; 4: 2 x0 x1 x2; 5: x0 x1 x3; 6: x0 x1 x2 x3; 7: 4 + 5 + 6.
    std::vector<Expr> exprs{load(0),
                            load(1),
                            load(2),
                            load(3),
                            product(2, {{0, 1}, {1, 1}, {2, 1}}),
                            product(1, {{0, 1}, {1, 1}, {3, 1}}),
                            product(1, {{0, 1}, {1, 1}, {2, 1}, {3, 1}}),
                            sum({{4, 1}, {5, 1}, {6, 1}})};
    std::vector<int> step_of_expr(exprs.size(), 0);
    std::vector<Step> steps(1);
    steps[0].assignments.push_back({"y", 0, 7});
    const std::vector<double> before = values(exprs);
    const int muls_before = multiplications(exprs);

    share_pairs(exprs, step_of_expr, steps);

    const std::vector<double> after = values(exprs); // also checks the order
    REQUIRE(step_of_expr.size() == exprs.size());
    const int root = steps[0].assignments[0].expr;
    CHECK(after[static_cast<std::size_t>(root)] == before[7]);
    // P = x0 x1 for the three products, then Q = x2 P for 2 x0 x1 x2 and
    // x0 x1 x2 x3: 2 Q, x3 P and x3 Q; 8 multiplications -> 5.
    CHECK(muls_before == 8);
    CHECK(multiplications(exprs) == 5);
    CHECK(exprs.size() == 10);
}

TEST_CASE("a product that is the pair itself is reused, and moved before its users") {
    // 4: x0 x1 x2 (before the pair), 5: x0 x1 x3, 6: x0 x1 (the pair).
    std::vector<Expr> exprs{load(0),
                            load(1),
                            load(2),
                            load(3),
                            product(1, {{0, 1}, {1, 1}, {2, 1}}),
                            product(3, {{0, 1}, {1, 1}, {3, 1}}),
                            product(1, {{0, 1}, {1, 1}})};
    std::vector<int> step_of_expr{0, 0, 0, 0, 0, 0, 1};
    std::vector<Step> steps(2);
    steps[0].assignments = {{"y", 0, 4}, {"y", 1, 5}};
    steps[1].assignments = {{"y", 2, 6}};
    const std::vector<double> before = values(exprs);

    share_pairs(exprs, step_of_expr, steps);

    CHECK(exprs.size() == 7); // no new product
    const std::vector<double> after = values(exprs);
    CHECK(after[static_cast<std::size_t>(steps[0].assignments[0].expr)] == before[4]);
    CHECK(after[static_cast<std::size_t>(steps[0].assignments[1].expr)] == before[5]);
    CHECK(after[static_cast<std::size_t>(steps[1].assignments[0].expr)] == before[6]);
    // The pair is now needed by the first step.
    CHECK(step_of_expr[static_cast<std::size_t>(steps[1].assignments[0].expr)] == 0);
}

TEST_CASE("sums sharing two terms in the same ratio compute them once") {
    // 4: x0 + 2 x1 + x2; 5: 3 x0 + 6 x1 + x3 (= 3 (x0 + 2 x1) + x3);
    // 6: x0 + 3 x1 (another ratio); 7: 0.1 x0 + 0.3 x1 (ratio 3 is not exact:
    // 0.3 / 0.1 * 0.1 != 0.3), all four summed by 8.
    std::vector<Expr> exprs{load(0),
                            load(1),
                            load(2),
                            load(3),
                            sum({{0, 1}, {1, 2}, {2, 1}}),
                            sum({{0, 3}, {1, 6}, {3, 1}}),
                            sum({{0, 1}, {1, 3}}),
                            sum({{0, 0.1}, {1, 0.3}}),
                            sum({{4, 1}, {5, 1}, {6, 1}, {7, 1}})};
    std::vector<int> step_of_expr(exprs.size(), 0);
    std::vector<Step> steps(1);
    steps[0].assignments.push_back({"y", 0, 8});
    const std::vector<double> before = values(exprs);

    share_pairs(exprs, step_of_expr, steps);

    const std::vector<double> after = values(exprs);
    CHECK(after[static_cast<std::size_t>(steps[0].assignments[0].expr)] == before[8]);
    REQUIRE(exprs.size() == 10); // one new sum: x0 + 2 x1
    int reading_it = 0;
    for (const Expr& e : exprs)
        for (const ExprOperand& op : e.operands)
            if (exprs[static_cast<std::size_t>(op.expr)].kind == ExprKind::add &&
                exprs[static_cast<std::size_t>(op.expr)].operands.size() == 2 &&
                exprs[static_cast<std::size_t>(op.expr)].operands[1].weight == 2.0)
                ++reading_it;
    CHECK(reading_it == 2); // 4 with weight 1, 5 with weight 3
}

TEST_CASE("products with no pair in common, and powers, are left alone") {
    std::vector<Expr> exprs{load(0),
                            load(1),
                            load(2),
                            load(3),
                            product(1, {{0, 1}, {1, 1}}),
                            product(1, {{2, 1}, {3, 1}}),
                            product(1, {{0, 2}, {1, 1}}),
                            product(1, {{0, 2}, {1, 1}, {2, 1}})};
    const std::vector<Expr> copy = exprs;
    std::vector<int> step_of_expr(exprs.size(), 0);
    std::vector<Step> steps(1);
    share_pairs(exprs, step_of_expr, steps);
    REQUIRE(exprs.size() == copy.size());
    for (std::size_t i = 0; i < exprs.size(); ++i)
        CHECK(exprs[i].operands.size() == copy[i].operands.size());
}
