#include "codegen/shared_products.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace yamsc::codegen {
namespace {

/// Two operands a < b of a product (both of exponent 1: ratio 1) or of a sum
/// (weights w_a and w_b = ratio w_a): the shared node is a*b or a + ratio b.
struct Pair {
    int a, b;
    double ratio;
    bool operator<(const Pair& o) const {
        return a != o.a ? a < o.a : b != o.b ? b < o.b : ratio < o.ratio;
    }
};

/// The operands of e that can be paired, by expression: a product's factors of
/// exponent 1, all the terms of a sum.
std::vector<ExprOperand> pairable(const Expr& e) {
    std::vector<ExprOperand> out;
    for (const ExprOperand& op : e.operands)
        if (e.kind == ExprKind::add || op.weight == 1.0) out.push_back(op);
    std::sort(out.begin(), out.end(),
              [](const ExprOperand& x, const ExprOperand& y) { return x.expr < y.expr; });
    out.erase(
        std::unique(out.begin(), out.end(),
                    [](const ExprOperand& x, const ExprOperand& y) { return x.expr == y.expr; }),
        out.end());
    return out;
}

/// The pair of x and y (x.expr < y.expr), or none when a sum's weights have no
/// exact ratio (the shared sum would round its terms differently).
std::optional<Pair> pair_of(const ExprOperand& x, const ExprOperand& y) {
    const double ratio = y.weight / x.weight;
    if (!std::isfinite(ratio) || ratio * x.weight != y.weight) return std::nullopt;
    return Pair{x.expr, y.expr, ratio};
}

/// The weight of operand `expr` in e (0: none pairable).
double weight_in(const Expr& e, int expr) {
    for (const ExprOperand& op : e.operands)
        if (op.expr == expr && (e.kind == ExprKind::add || op.weight == 1.0)) return op.weight;
    return 0.0;
}

/// Whether e contains the pair, and the weight of its first operand.
std::optional<double> contains(const Expr& e, const Pair& p) {
    const double wa = weight_in(e, p.a), wb = weight_in(e, p.b);
    if (wa == 0.0 || wb == 0.0 || wa * p.ratio != wb) return std::nullopt;
    return wa;
}

/// Whether e is exactly the shared node of the pair.
bool is_pair(const Expr& e, ExprKind kind, const Pair& p) {
    const double neutral = kind == ExprKind::mul ? 1.0 : 0.0;
    return e.kind == kind && e.value == neutral && e.operands.size() == 2 &&
           contains(e, p).value_or(0.0) == 1.0;
}

/// Each pair shared by the expressions `scan`, with the expressions that
/// contain it, most shared first (ties by the pair, so the result depends on
/// structure only). With `fresh`, only pairs with a fresh operand.
std::vector<std::pair<Pair, std::vector<int>>> shared_pairs(const std::vector<Expr>& exprs,
                                                            const std::vector<int>& scan,
                                                            const std::vector<bool>* fresh) {
    std::vector<std::pair<Pair, int>> found; // sorted and grouped below: no map
    for (int i : scan) {
        const std::vector<ExprOperand> ops = pairable(exprs[static_cast<std::size_t>(i)]);
        for (std::size_t x = 0; x < ops.size(); ++x)
            for (std::size_t y = x + 1; y < ops.size(); ++y) {
                if (fresh && !(*fresh)[static_cast<std::size_t>(ops[x].expr)] &&
                    !(*fresh)[static_cast<std::size_t>(ops[y].expr)])
                    continue;
                if (const auto p = pair_of(ops[x], ops[y])) found.emplace_back(*p, i);
            }
    }
    std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) {
        return x.first < y.first || (!(y.first < x.first) && x.second < y.second);
    });
    std::vector<std::pair<Pair, std::vector<int>>> out;
    for (std::size_t i = 0; i < found.size();) {
        std::size_t j = i;
        std::vector<int> users;
        for (; j < found.size() && !(found[i].first < found[j].first); ++j)
            if (users.empty() || users.back() != found[j].second) users.push_back(found[j].second);
        if (users.size() > 1) out.emplace_back(found[i].first, std::move(users));
        i = j;
    }
    std::stable_sort(out.begin(), out.end(), [](const auto& x, const auto& y) {
        return x.second.size() > y.second.size();
    });
    return out;
}

/// Replaces the pair's operands of e by the shared node `with`, of weight wa.
void replace_pair(Expr& e, const Pair& p, int with, double wa) {
    std::vector<ExprOperand> kept;
    bool dropped_a = false, dropped_b = false;
    for (const ExprOperand& op : e.operands) {
        const bool pairable_op = e.kind == ExprKind::add || op.weight == 1.0;
        if (pairable_op && op.expr == p.a && !dropped_a) {
            dropped_a = true;
            continue;
        }
        if (pairable_op && op.expr == p.b && !dropped_b) {
            dropped_b = true;
            continue;
        }
        kept.push_back(op);
    }
    kept.push_back({with, wa});
    e.operands = std::move(kept);
}

/// Greedy rounds for one kind of node: the pairs counted at the start of a
/// round are taken in order while still shared. A pair not shared at the start
/// of a round is never shared later unless one of its operands is a node the
/// last round made or reused, so later rounds count only those pairs, in the
/// expressions that read such a node.
void share_pairs_of(ExprKind kind, std::vector<Expr>& exprs, std::vector<int>& step_of_expr) {
    std::vector<int> scan;
    for (std::size_t i = 0; i < exprs.size(); ++i)
        if (exprs[i].kind == kind) scan.push_back(static_cast<int>(i));
    std::vector<bool> fresh;
    for (bool first = true; !scan.empty(); first = false) {
        std::vector<int> shared_nodes;
        for (auto& [pair, candidates] : shared_pairs(exprs, scan, first ? nullptr : &fresh)) {
            std::vector<std::pair<int, double>> users; // expression, weight of a
            int existing = -1;
            for (int u : candidates) {
                const Expr& e = exprs[static_cast<std::size_t>(u)];
                const std::optional<double> wa = contains(e, pair);
                if (!wa) continue;
                if (is_pair(e, kind, pair))
                    existing = u;
                else
                    users.emplace_back(u, *wa);
            }
            if (users.empty() || users.size() + (existing >= 0 ? 1 : 0) < 2) continue;
            int with = existing;
            if (with < 0) {
                Expr shared;
                shared.kind = kind;
                shared.value = kind == ExprKind::mul ? 1.0 : 0.0;
                shared.operands = {{pair.a, 1.0}, {pair.b, pair.ratio}};
                with = static_cast<int>(exprs.size());
                exprs.push_back(std::move(shared));
                step_of_expr.push_back(step_of_expr[static_cast<std::size_t>(users.front().first)]);
            }
            for (const auto& [u, wa] : users) {
                replace_pair(exprs[static_cast<std::size_t>(u)], pair, with, wa);
                auto& step = step_of_expr[static_cast<std::size_t>(with)];
                step = std::min(step, step_of_expr[static_cast<std::size_t>(u)]);
            }
            shared_nodes.push_back(with);
        }
        fresh.assign(exprs.size(), false);
        for (int n : shared_nodes) fresh[static_cast<std::size_t>(n)] = true;
        scan.clear();
        for (std::size_t i = 0; i < exprs.size() && !shared_nodes.empty(); ++i)
            if (exprs[i].kind == kind &&
                std::any_of(exprs[i].operands.begin(), exprs[i].operands.end(),
                            [&](const ExprOperand& op) {
                                return fresh[static_cast<std::size_t>(op.expr)];
                            }))
                scan.push_back(static_cast<int>(i));
    }
}

} // namespace

void share_pairs(std::vector<Expr>& exprs, std::vector<int>& step_of_expr,
                 std::vector<Step>& steps) {
    const std::size_t original = exprs.size(); // new products go after these
    share_pairs_of(ExprKind::mul, exprs, step_of_expr);
    share_pairs_of(ExprKind::add, exprs, step_of_expr);
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
