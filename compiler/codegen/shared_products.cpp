#include "codegen/shared_products.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace yamsc::codegen {
namespace {

using Pair = std::pair<int, int>; // two factor expressions, first < second

/// The factors of exponent 1 of a product, sorted.
std::vector<int> unit_factors(const Expr& e) {
    std::vector<int> out;
    for (const ExprOperand& op : e.operands)
        if (op.weight == 1.0) out.push_back(op.expr);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

bool has_factor(const Expr& e, int f) {
    return std::any_of(e.operands.begin(), e.operands.end(),
                       [f](const ExprOperand& op) { return op.expr == f && op.weight == 1.0; });
}

/// Whether e is exactly the product a*b.
bool is_pair(const Expr& e, const Pair& p) {
    return e.kind == ExprKind::mul && e.value == 1.0 && e.operands.size() == 2 &&
           has_factor(e, p.first) && has_factor(e, p.second);
}

/// Each shared pair with the products that contain it, most shared first (ties
/// by the pair, so the result depends on structure only).
std::vector<std::pair<Pair, std::vector<int>>> shared_pairs(const std::vector<Expr>& exprs) {
    std::map<Pair, std::vector<int>> users;
    for (std::size_t i = 0; i < exprs.size(); ++i) {
        if (exprs[i].kind != ExprKind::mul) continue;
        const std::vector<int> f = unit_factors(exprs[i]);
        for (std::size_t a = 0; a < f.size(); ++a)
            for (std::size_t b = a + 1; b < f.size(); ++b)
                users[{f[a], f[b]}].push_back(static_cast<int>(i));
    }
    std::vector<std::pair<Pair, std::vector<int>>> out;
    for (auto& [pair, list] : users)
        if (list.size() > 1) out.emplace_back(pair, std::move(list));
    std::stable_sort(out.begin(), out.end(), [](const auto& x, const auto& y) {
        return x.second.size() > y.second.size();
    });
    return out;
}

/// Replaces the factors a and b of product e by the single factor `with`.
void replace_pair(Expr& e, const Pair& p, int with) {
    std::vector<ExprOperand> kept;
    bool dropped_a = false, dropped_b = false;
    for (const ExprOperand& op : e.operands) {
        if (op.weight == 1.0 && op.expr == p.first && !dropped_a) {
            dropped_a = true;
            continue;
        }
        if (op.weight == 1.0 && op.expr == p.second && !dropped_b) {
            dropped_b = true;
            continue;
        }
        kept.push_back(op);
    }
    kept.push_back({with, 1.0});
    e.operands = std::move(kept);
}

} // namespace

void share_factor_pairs(std::vector<Expr>& exprs, std::vector<int>& step_of_expr,
                        std::vector<Step>& steps) {
    const std::size_t original = exprs.size(); // new products go after these
    // Rounds: the pairs counted at the start of a round are taken in order while
    // they are still shared; a round's new products can share pairs in the next.
    for (bool changed = true; changed;) {
        changed = false;
        for (auto& [pair, candidates] : shared_pairs(exprs)) {
            std::vector<int> users;
            int existing = -1;
            for (int u : candidates) {
                const Expr& e = exprs[static_cast<std::size_t>(u)];
                if (!has_factor(e, pair.first) || !has_factor(e, pair.second)) continue;
                if (is_pair(e, pair))
                    existing = u;
                else
                    users.push_back(u);
            }
            if (users.size() + (existing >= 0 ? 1 : 0) < 2 || users.empty()) continue;
            int with = existing;
            if (with < 0) {
                Expr product;
                product.kind = ExprKind::mul;
                product.value = 1.0;
                product.operands = {{pair.first, 1.0}, {pair.second, 1.0}};
                with = static_cast<int>(exprs.size());
                exprs.push_back(std::move(product));
                step_of_expr.push_back(step_of_expr[static_cast<std::size_t>(users.front())]);
            }
            auto& step = step_of_expr[static_cast<std::size_t>(with)];
            for (int u : users) {
                replace_pair(exprs[static_cast<std::size_t>(u)], pair, with);
                step = std::min(step, step_of_expr[static_cast<std::size_t>(u)]);
            }
            changed = true;
        }
    }
    // Operands before users: the old order, each expression preceded by the
    // operands not placed yet (a new product, or an old one a user now reads).
    // Only such products are out of order, so the recursion is as deep as
    // products of pairs nest.
    std::vector<int> position(exprs.size(), -1);
    std::vector<int> order;
    order.reserve(exprs.size());
    auto place = [&](auto& self, int i) -> void {
        if (position[static_cast<std::size_t>(i)] >= 0) return;
        for (const ExprOperand& op : exprs[static_cast<std::size_t>(i)].operands)
            self(self, op.expr);
        position[static_cast<std::size_t>(i)] = static_cast<int>(order.size());
        order.push_back(i);
    };
    for (std::size_t i = 0; i < original; ++i) place(place, static_cast<int>(i));
    std::vector<Expr> reordered;
    std::vector<int> steps_reordered;
    reordered.reserve(exprs.size());
    for (int i : order) {
        Expr e = std::move(exprs[static_cast<std::size_t>(i)]);
        for (ExprOperand& op : e.operands) op.expr = position[static_cast<std::size_t>(op.expr)];
        reordered.push_back(std::move(e));
        steps_reordered.push_back(step_of_expr[static_cast<std::size_t>(i)]);
    }
    exprs = std::move(reordered);
    step_of_expr = std::move(steps_reordered);
    for (Step& s : steps)
        for (Assignment& a : s.assignments) a.expr = position[static_cast<std::size_t>(a.expr)];
}

} // namespace yamsc::codegen
