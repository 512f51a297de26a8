#include "passes/taylor.hpp"

#include "diag/diagnostics.hpp"
#include "passes/forward.hpp"

#include <cmath>
#include <map>

namespace yamsc::passes {

using ir::Function;
using ir::NodeId;
using ir::NodeKind;
using ir::Operand;

namespace {

/// All exponent vectors of `n` variables with total degree <= `order`, by degree
/// (the n monomials of degree 1 come right after the constant, in variable order).
std::vector<std::vector<int>> monomials_up_to(std::size_t n, int order) {
    std::vector<std::vector<int>> out{std::vector<int>(n, 0)};
    std::vector<std::vector<int>> previous = out;
    for (int d = 1; d <= order; ++d) {
        // Each monomial of degree d-1 times one variable at or after its last
        // non-zero exponent: every monomial of degree d exactly once.
        std::vector<std::vector<int>> current;
        for (const auto& m : previous) {
            std::size_t last = 0;
            for (std::size_t i = 0; i < n; ++i)
                if (m[i] > 0) last = i;
            for (std::size_t i = last; i < n; ++i) {
                std::vector<int> next = m;
                ++next[i];
                current.push_back(next);
            }
        }
        out.insert(out.end(), current.begin(), current.end());
        previous = std::move(current);
    }
    return out;
}

bool is_whole(double x) {
    return x >= 0 && x <= 64 && std::floor(x) == x;
}

/// f(args), a number when every argument is one and the value is finite: the
/// expansion point is usually 0, and sin(0) must vanish, not stay a call.
NodeId call(ir::Graph& g, Function f, const std::vector<NodeId>& args) {
    bool numbers = true;
    for (NodeId a : args) numbers = numbers && g.node(a).kind == NodeKind::number;
    if (numbers) {
        const double v =
            ir::evaluate(f, g.node(args[0]).value, args.size() > 1 ? g.node(args[1]).value : 0.0);
        if (std::isfinite(v)) return g.number(v);
    }
    if (f == Function::sqrt) return g.mul({{args[0], 0.5}}, 1.0);
    if (f == Function::pow) return g.power(args[0], args[1]);
    return g.call(f, args);
}

/// The nodes of `from` up to `root` rebuilt in `to`, every symbol replaced by
/// `value` (`from` has one symbol).
NodeId copy_substituted(const ir::Graph& from, NodeId root, ir::Graph& to, NodeId value) {
    std::vector<NodeId> mapped(root + 1);
    for (NodeId id = 0; id <= root; ++id) {
        const ir::Node& n = from.node(id);
        std::vector<Operand> ops;
        for (const Operand& op : from.operands(id)) ops.push_back({mapped[op.node], op.weight});
        switch (n.kind) {
        case NodeKind::number:
            mapped[id] = to.number(n.value);
            break;
        case NodeKind::symbol:
            mapped[id] = value;
            break;
        case NodeKind::add:
            mapped[id] = to.add(std::move(ops), n.value);
            break;
        case NodeKind::mul:
            mapped[id] = to.mul(std::move(ops), n.value);
            break;
        case NodeKind::call: {
            std::vector<NodeId> args;
            for (const Operand& op : ops) args.push_back(op.node);
            mapped[id] = call(to, n.function, args);
            break;
        }
        }
    }
    return mapped[root];
}

} // namespace

TaylorExpansion::TaylorExpansion(ir::Graph& graph, const std::vector<ir::SymbolRef>& group,
                                 int order)
    : graph_(graph), variable_to_group_(static_cast<std::size_t>(graph.variables().count()), -1),
      mask_(graph.dependence_words(), 0), order_(order), zero_(graph.number(0.0)),
      one_(graph.number(1.0)) {
    std::vector<NodeId> symbol_nodes;
    for (std::size_t i = 0; i < group.size(); ++i) {
        const int v = graph.variables().of(group[i]);
        if (v < 0) throw diag::InternalError("approx: a symbol that is not a variable");
        variable_to_group_[static_cast<std::size_t>(v)] = static_cast<int>(i);
        mask_[static_cast<std::size_t>(v) / 64] |= std::uint64_t{1} << (v % 64);
        symbol_nodes.push_back(graph.symbol(group[i]));
    }
    monomials_ = monomials_up_to(group.size(), order_);
    std::map<std::vector<int>, int> index;
    for (std::size_t k = 0; k < monomials_.size(); ++k) {
        index[monomials_[k]] = static_cast<int>(k);
        int d = 0;
        std::vector<Operand> factors;
        for (std::size_t i = 0; i < group.size(); ++i) {
            d += monomials_[k][i];
            if (monomials_[k][i] > 0)
                factors.push_back({symbol_nodes[i], static_cast<double>(monomials_[k][i])});
        }
        degree_.push_back(d);
        monomial_values_.push_back(graph.mul(std::move(factors), 1.0));
    }
    const std::size_t T = monomials_.size();
    product_index_.assign(T, std::vector<int>(T, -1));
    for (std::size_t i = 0; i < T; ++i)
        for (std::size_t j = 0; j < T; ++j) {
            if (degree_[i] + degree_[j] > order_) continue;
            std::vector<int> m = monomials_[i];
            for (std::size_t v = 0; v < m.size(); ++v) m[v] += monomials_[j][v];
            product_index_[i][j] = index.at(m);
        }
}

NodeId TaylorExpansion::operator()(NodeId node) {
    const Series s = series(node);
    std::vector<Operand> terms;
    for (std::size_t k = 0; k < s.size(); ++k)
        if (s[k] != zero_) terms.push_back({times(s[k], monomial_values_[k]), 1.0});
    return graph_.add(std::move(terms), 0.0);
}

NodeId TaylorExpansion::times(NodeId a, NodeId b) {
    return graph_.mul({{a, 1.0}, {b, 1.0}}, 1.0);
}

TaylorExpansion::Series TaylorExpansion::series(NodeId node) {
    if (!depends(node)) return constant(node);
    if (auto it = memo_.find(node); it != memo_.end()) return it->second;
    Series s = compute(node);
    return memo_.emplace(node, std::move(s)).first->second;
}

TaylorExpansion::Series TaylorExpansion::constant(NodeId c) const {
    Series s(monomials_.size(), zero_);
    s[0] = c;
    return s;
}

TaylorExpansion::Series TaylorExpansion::add_to(Series a, const Series& b) {
    for (std::size_t k = 0; k < a.size(); ++k)
        if (b[k] != zero_) a[k] = graph_.add({{a[k], 1.0}, {b[k], 1.0}}, 0.0);
    return a;
}

TaylorExpansion::Series TaylorExpansion::scale(const Series& a, NodeId c) {
    Series out(a.size(), zero_);
    for (std::size_t k = 0; k < a.size(); ++k)
        if (a[k] != zero_) out[k] = times(a[k], c);
    return out;
}

TaylorExpansion::Series TaylorExpansion::multiply(const Series& a, const Series& b) {
    const std::size_t T = a.size();
    std::vector<std::vector<Operand>> terms(T);
    for (std::size_t i = 0; i < T; ++i) {
        if (a[i] == zero_) continue;
        for (std::size_t j = 0; j < T; ++j) {
            const int k = product_index_[i][j];
            if (k < 0 || b[j] == zero_) continue;
            terms[static_cast<std::size_t>(k)].push_back({times(a[i], b[j]), 1.0});
        }
    }
    Series out(T);
    for (std::size_t k = 0; k < T; ++k) out[k] = graph_.add(std::move(terms[k]), 0.0);
    return out;
}

TaylorExpansion::Series TaylorExpansion::compose(const std::vector<NodeId>& c, const Series& r) {
    Series out = constant(c[0]);
    Series r_k = constant(one_);
    for (int k = 1; k <= order_; ++k) {
        r_k = multiply(r_k, r); // starts at degree k: r has no constant term
        const NodeId ck = c[static_cast<std::size_t>(k)];
        if (ck != zero_) out = add_to(std::move(out), scale(r_k, ck));
    }
    return out;
}

TaylorExpansion::Series TaylorExpansion::compute(NodeId node) {
    ir::Graph& g = graph_;
    // Copies: new nodes may move the graph's storage.
    const ir::Node n = g.node(node);
    const ir::OperandSpan span = g.operands(node);
    const std::vector<Operand> ops(span.begin(), span.end());
    switch (n.kind) {
    case NodeKind::number:
        return constant(node);
    case NodeKind::symbol: {
        Series s = constant(zero_);
        const int v = g.variables().of(n.symbol);
        s[1 + static_cast<std::size_t>(variable_to_group_.at(static_cast<std::size_t>(v)))] = one_;
        return s;
    }
    case NodeKind::add: {
        std::vector<std::vector<Operand>> terms(monomials_.size());
        for (const Operand& op : ops) {
            const Series s = series(op.node);
            for (std::size_t k = 0; k < s.size(); ++k)
                if (s[k] != zero_) terms[k].push_back({s[k], op.weight});
        }
        Series out(monomials_.size());
        for (std::size_t k = 0; k < out.size(); ++k)
            out[k] = g.add(std::move(terms[k]), k == 0 ? n.value : 0.0);
        return out;
    }
    case NodeKind::mul: {
        // Factors without the group's variables multiply the result once, at the end.
        std::vector<Operand> independent;
        Series out = constant(one_);
        for (const Operand& f : ops) {
            if (!depends(f.node))
                independent.push_back(f);
            else if (f.weight == 1.0)
                out = multiply(out, series(f.node));
            else
                out = multiply(out, power(series(f.node), g.number(f.weight)));
        }
        return scale(out, g.mul(std::move(independent), n.value));
    }
    case NodeKind::call:
        if (n.function == Function::sqrt) return power(series(ops[0].node), g.number(0.5));
        if (n.function == Function::pow) {
            if (depends(ops[1].node))
                throw NotExpandable("a power whose exponent depends on the approximated symbols",
                                    true);
            return power(series(ops[0].node), ops[1].node);
        }
        if (n.function == Function::atan2 || n.function == Function::abs)
            throw NotExpandable(std::string("the function ") +
                                    std::string(ir::info(n.function).name) +
                                    " of the approximated symbols",
                                true);
        return function(n.function, ops[0].node);
    }
    throw diag::InternalError("approx: unknown node kind");
}

TaylorExpansion::Series TaylorExpansion::power(const Series& s, NodeId exponent) {
    ir::Graph& g = graph_;
    if (g.node(exponent).kind == NodeKind::number && is_whole(g.node(exponent).value)) {
        auto n = static_cast<long>(g.node(exponent).value);
        Series out = constant(one_), square = s;
        while (n > 0) { // binary powering; every product is truncated
            if (n & 1) out = multiply(out, square);
            n >>= 1;
            if (n > 0) square = multiply(square, square);
        }
        return out;
    }
    // (b0 + r)^α = b0^α Σ binom(α, k) (r / b0)^k
    const NodeId b0 = s[0];
    if (b0 == zero_)
        throw NotExpandable("a division by (or a root of) an expression that is zero when the "
                            "approximated symbols are",
                            false);
    Series r = scale(s, g.mul({{b0, -1.0}}, 1.0));
    r[0] = zero_;
    std::vector<NodeId> c{one_};
    for (int k = 1; k <= order_; ++k) {
        const NodeId alpha_minus = g.add({{exponent, 1.0}}, -(k - 1.0));
        c.push_back(g.mul({{c.back(), 1.0}, {alpha_minus, 1.0}}, 1.0 / k));
    }
    return scale(compose(c, r), g.power(b0, exponent));
}

TaylorExpansion::Series TaylorExpansion::function(Function f, NodeId argument) {
    Series r = series(argument);
    const NodeId a0 = r[0];
    r[0] = zero_;
    return compose(derivatives_at(f, a0), r);
}

std::vector<NodeId> TaylorExpansion::derivatives_at(Function f, NodeId a0) {
    ir::Graph& g = graph_;
    std::vector<NodeId> c;
    double factorial = 1;
    if (f == Function::sin || f == Function::cos) {
        // The derivatives cycle through sin, cos, -sin, -cos.
        const NodeId s = call(g, Function::sin, {a0}), co = call(g, Function::cos, {a0});
        const NodeId cycle[4] = {s, co, s, co};
        const double sign[4] = {1, 1, -1, -1};
        const int shift = f == Function::sin ? 0 : 1;
        for (int k = 0; k <= order_; ++k) {
            if (k > 0) factorial *= k;
            const int i = (k + shift) % 4;
            c.push_back(g.mul({{cycle[i], 1.0}}, sign[i] / factorial));
        }
        return c;
    }
    // f^(k)(x) in a graph of its own whose one variable is x, then x = a0.
    ir::Graph scratch(g.max_multiplied_power(), ir::Variables{1, 0, 0});
    NodeId d = scratch.call(f, {scratch.symbol({ir::SymbolKind::q, 0})});
    ForwardDerivative d_dx(scratch, 0);
    for (int k = 0; k <= order_; ++k) {
        if (k > 0) {
            factorial *= k;
            d = d_dx(d);
        }
        c.push_back(g.mul({{copy_substituted(scratch, d, g, a0), 1.0}}, 1.0 / factorial));
    }
    return c;
}

} // namespace yamsc::passes
