#include "passes/forward.hpp"

#include "diag/diagnostics.hpp"

#include <utility>

namespace yamsc::passes {

using ir::Function;
using ir::NodeId;
using ir::NodeKind;
using ir::Operand;

namespace {

/// A node as a power base^exponent: sqrt(b) is b^(1/2), pow(b, c) for a number c
/// is b^c, anything else x^1. The Graph writes powers that are not small
/// integers as these calls; differentiating the power itself gives the same
/// expression whichever way the power was written.
std::pair<NodeId, double> power_view(const ir::Graph& g, NodeId id) {
    const ir::Node& n = g.node(id);
    if (n.kind == NodeKind::call && n.function == Function::sqrt)
        return {g.operands(id)[0].node, 0.5};
    if (n.kind == NodeKind::call && n.function == Function::pow) {
        const NodeId exponent = g.operands(id)[1].node;
        if (g.node(exponent).kind == NodeKind::number)
            return {g.operands(id)[0].node, g.node(exponent).value};
    }
    return {id, 1.0};
}

} // namespace

ForwardDerivative::ForwardDerivative(ir::Graph& graph, std::size_t variable)
    : ForwardDerivative(graph, [&] {
          std::vector<NodeId> seeds(static_cast<std::size_t>(graph.variables().count()),
                                    graph.number(0.0));
          seeds.at(variable) = graph.number(1.0);
          return seeds;
      }()) {}

ForwardDerivative::ForwardDerivative(ir::Graph& graph, std::vector<NodeId> seeds)
    : graph_(graph), zero_(graph.number(0.0)), seeds_(std::move(seeds)),
      mask_(graph.dependence_words(), 0) {
    if (seeds_.size() != static_cast<std::size_t>(graph.variables().count()))
        throw diag::InternalError("a directional derivative needs one seed per variable");
    for (std::size_t v = 0; v < seeds_.size(); ++v)
        if (seeds_[v] != zero_) mask_[v / 64] |= std::uint64_t{1} << (v % 64);
}

NodeId ForwardDerivative::memo(NodeId node) const {
    if (!relevant(node)) return zero_;
    return done_.at(node);
}

// d(node) from the derivatives of its operands (all in done_ already).
NodeId ForwardDerivative::rule(NodeId node) {
    ir::Graph& g = graph_;
    const ir::Node n = g.node(node); // copies: the storage moves as nodes are added
    const ir::OperandSpan span = g.operands(node);
    const std::vector<Operand> ops(span.begin(), span.end());
    switch (n.kind) {
    case NodeKind::number:
        return zero_;
    case NodeKind::symbol: {
        const int v = g.variables().of(n.symbol);
        return v < 0 ? zero_ : seeds_[static_cast<std::size_t>(v)];
    }
    case NodeKind::add: {
        std::vector<Operand> terms;
        for (const Operand& op : ops) {
            const NodeId d = memo(op.node);
            if (d != zero_) terms.push_back({d, op.weight});
        }
        return g.add(std::move(terms), 0.0);
    }
    case NodeKind::mul: {
        // d(c prod x_i^e_i) = sum_i c e_i x_i^(e_i - 1) dx_i prod_(j != i) x_j^e_j,
        // with each x_i^e_i read as a power of its base (power_view).
        std::vector<Operand> terms;
        for (std::size_t i = 0; i < ops.size(); ++i) {
            const auto [base, exponent] = power_view(g, ops[i].node);
            const NodeId d = memo(base);
            if (d == zero_) continue;
            const double e = exponent * ops[i].weight;
            std::vector<Operand> product = ops;
            product[i] = {base, e - 1.0};
            product.push_back({d, 1.0});
            terms.push_back({g.mul(std::move(product), n.value * e), 1.0});
        }
        return g.add(std::move(terms), 0.0);
    }
    case NodeKind::call:
        break;
    }
    const NodeId a = ops[0].node;
    const NodeId da = memo(a);
    auto mul = [&g](std::vector<Operand> f, double c = 1.0) { return g.mul(std::move(f), c); };
    auto add = [&g](std::vector<Operand> t, double c = 0.0) { return g.add(std::move(t), c); };
    if (n.function == Function::atan2) {
        // d atan2(y, x) = (x dy - y dx) / (x^2 + y^2)
        const NodeId y = a, x = ops[1].node, dy = da, dx = memo(ops[1].node);
        std::vector<Operand> numerator;
        if (dy != zero_) numerator.push_back({mul({{x, 1.0}, {dy, 1.0}}), 1.0});
        if (dx != zero_) numerator.push_back({mul({{y, 1.0}, {dx, 1.0}}), -1.0});
        const NodeId denominator = add({{mul({{x, 2.0}}), 1.0}, {mul({{y, 2.0}}), 1.0}});
        return mul({{add(std::move(numerator)), 1.0}, {denominator, -1.0}});
    }
    if (n.function == Function::pow || n.function == Function::sqrt) {
        const auto [base, exponent] = power_view(g, node);
        if (base != node) { // a numeric power: e b^(e - 1) db
            const NodeId db = memo(base);
            if (db == zero_) return zero_;
            return mul({{base, exponent - 1.0}, {db, 1.0}}, exponent);
        }
        // d(b^x) = b^x (dx log b + x db / b)
        const NodeId b = ops[0].node, x = ops[1].node;
        const NodeId db = memo(b), dx = memo(x);
        std::vector<Operand> inner;
        if (dx != zero_)
            inner.push_back({mul({{dx, 1.0}, {g.call(Function::log, {b}), 1.0}}), 1.0});
        if (db != zero_) inner.push_back({mul({{x, 1.0}, {db, 1.0}, {b, -1.0}}), 1.0});
        return mul({{node, 1.0}, {add(std::move(inner)), 1.0}});
    }
    if (da == zero_) return zero_;
    const NodeId a2 = mul({{a, 2.0}});
    NodeId outer = zero_;
    switch (n.function) {
    case Function::sin:
        outer = g.call(Function::cos, {a});
        break;
    case Function::cos:
        outer = mul({{g.call(Function::sin, {a}), 1.0}}, -1.0);
        break;
    case Function::tan:
        outer = add({{mul({{node, 2.0}}), 1.0}}, 1.0);
        break;
    case Function::asin:
        outer = mul({{add({{a2, -1.0}}, 1.0), -0.5}});
        break;
    case Function::acos:
        outer = mul({{add({{a2, -1.0}}, 1.0), -0.5}}, -1.0);
        break;
    case Function::atan:
        outer = mul({{add({{a2, 1.0}}, 1.0), -1.0}});
        break;
    case Function::sinh:
        outer = g.call(Function::cosh, {a});
        break;
    case Function::cosh:
        outer = g.call(Function::sinh, {a});
        break;
    case Function::tanh:
        outer = add({{mul({{node, 2.0}}), -1.0}}, 1.0);
        break;
    case Function::asinh:
        outer = mul({{add({{a2, 1.0}}, 1.0), -0.5}});
        break;
    case Function::acosh:
        outer = mul({{add({{a2, 1.0}}, -1.0), -0.5}});
        break;
    case Function::atanh:
        outer = mul({{add({{a2, -1.0}}, 1.0), -1.0}});
        break;
    case Function::exp:
        outer = node;
        break;
    case Function::log:
        outer = mul({{a, -1.0}});
        break;
    case Function::abs:
        outer = mul({{a, 1.0}, {node, -1.0}});
        break;
    case Function::atan2:
    case Function::sqrt:
    case Function::pow:
        break; // handled above
    }
    return mul({{outer, 1.0}, {da, 1.0}});
}

NodeId ForwardDerivative::operator()(NodeId root) {
    if (!relevant(root)) return zero_;
    if (auto it = done_.find(root); it != done_.end()) return it->second;
    // Post-order over the operands that depend on a seeded variable and are not done.
    std::vector<std::pair<NodeId, std::uint32_t>> stack{{root, 0}};
    while (!stack.empty()) {
        auto& [id, next] = stack.back();
        if (next < graph_.node(id).operand_count) {
            const NodeId child = graph_.operands(id)[next++].node;
            if (relevant(child) && done_.find(child) == done_.end()) stack.emplace_back(child, 0);
            continue;
        }
        const NodeId node = id;
        stack.pop_back();
        if (done_.find(node) == done_.end()) done_.emplace(node, rule(node));
    }
    return done_.at(root);
}

} // namespace yamsc::passes
