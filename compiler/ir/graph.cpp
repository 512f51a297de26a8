#include "ir/graph.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace yamsc::ir {
namespace {

std::uint64_t bits_of(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

// splitmix64's finaliser: a fixed, well-mixing function of the input only.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

std::uint64_t combine(std::uint64_t h, std::uint64_t v) {
    return mix(h ^ mix(v));
}

int compare_u64(std::uint64_t a, std::uint64_t b) {
    return a < b ? -1 : (a > b ? 1 : 0);
}

bool is_small_integer(double w, int limit) {
    return w == std::floor(w) && std::fabs(w) <= static_cast<double>(limit);
}

int kind_rank(NodeKind kind) {
    switch (kind) {
    case NodeKind::symbol:
        return 0;
    case NodeKind::number:
        return 1;
    case NodeKind::call:
        return 2;
    case NodeKind::mul:
        return 3;
    case NodeKind::add:
        return 4;
    }
    return 5;
}

double without_negative_zero(double v) {
    return v == 0.0 ? 0.0 : v;
}

} // namespace

int Variables::of(SymbolRef s) const {
    switch (s.kind) {
    case SymbolKind::q:
        return s.index < nq ? s.index : -1;
    case SymbolKind::qd:
        return s.index < nq ? nq + s.index : -1;
    case SymbolKind::input:
        return s.index < nu ? 2 * nq + s.index : -1;
    case SymbolKind::param:
        return s.index < np ? 2 * nq + nu + s.index : -1;
    default:
        return -1;
    }
}

bool Graph::same_content(NodeId id, const Node& n, const std::vector<Operand>& operands) const {
    const Node& a = nodes_[id];
    if (a.hash != n.hash || a.kind != n.kind || a.function != n.function ||
        a.symbol.kind != n.symbol.kind || a.symbol.index != n.symbol.index ||
        bits_of(a.value) != bits_of(n.value) || a.operand_count != operands.size())
        return false;
    const Operand* mine = operands_.data() + a.first_operand;
    for (std::size_t i = 0; i < operands.size(); ++i) {
        if (mine[i].node != operands[i].node ||
            bits_of(mine[i].weight) != bits_of(operands[i].weight))
            return false;
    }
    return true;
}

void Graph::grow_table() {
    table_.assign(table_.empty() ? 1024 : 2 * table_.size(), empty_slot);
    const std::size_t mask = table_.size() - 1;
    for (NodeId id = 0; id < nodes_.size(); ++id) {
        std::size_t slot = nodes_[id].hash & mask;
        while (table_[slot] != empty_slot) slot = (slot + 1) & mask;
        table_[slot] = id;
    }
}

NodeId Graph::intern(Node n, const std::vector<Operand>& operands) {
    n.value = without_negative_zero(n.value);
    std::uint64_t h = mix(static_cast<std::uint64_t>(n.kind) + 1);
    h = combine(h, static_cast<std::uint64_t>(n.function));
    h = combine(h, static_cast<std::uint64_t>(n.symbol.kind));
    h = combine(h, static_cast<std::uint64_t>(n.symbol.index));
    h = combine(h, bits_of(n.value));
    std::uint32_t depends = n.kind == NodeKind::symbol ? 1u << static_cast<int>(n.symbol.kind) : 0u;
    for (const Operand& op : operands) {
        h = combine(h, nodes_[op.node].hash);
        h = combine(h, bits_of(op.weight));
        depends |= nodes_[op.node].depends;
    }
    n.hash = h;
    n.depends = depends;

    if (2 * (nodes_.size() + 1) > table_.size()) grow_table();
    const std::size_t mask = table_.size() - 1;
    std::size_t slot = h & mask;
    for (; table_[slot] != empty_slot; slot = (slot + 1) & mask)
        if (same_content(table_[slot], n, operands)) return table_[slot];

    const auto id = static_cast<NodeId>(nodes_.size());
    // Dependence: the variable itself, or the union over the operands.
    dependence_.resize(dependence_.size() + words_, 0);
    std::uint64_t* mine = dependence_.data() + static_cast<std::size_t>(id) * words_;
    if (n.kind == NodeKind::symbol) {
        const int v = variables_.of(n.symbol);
        if (v >= 0) mine[v / 64] |= std::uint64_t{1} << (v % 64);
    }
    for (const Operand& op : operands) {
        const std::uint64_t* theirs =
            dependence_.data() + static_cast<std::size_t>(op.node) * words_;
        for (std::size_t w = 0; w < words_; ++w) mine[w] |= theirs[w];
    }
    n.first_operand = static_cast<std::uint32_t>(operands_.size());
    n.operand_count = static_cast<std::uint32_t>(operands.size());
    operands_.insert(operands_.end(), operands.begin(), operands.end());
    nodes_.push_back(n);
    table_[slot] = id;
    return id;
}

std::vector<Operand> Graph::operand_copy(NodeId id) const {
    const OperandSpan span = operands(id);
    return std::vector<Operand>(span.begin(), span.end());
}

// Readable and structural: symbols first (in declaration order: t, q, q', q'',
// u, p, a), then numbers, calls, products and sums; compound nodes of one kind
// by structural hash, and only a full 64-bit collision compares contents.
int Graph::compare(NodeId a, NodeId b) const {
    if (a == b) return 0;
    const Node& x = nodes_[a];
    const Node& y = nodes_[b];
    if (x.kind != y.kind) return kind_rank(x.kind) < kind_rank(y.kind) ? -1 : 1;
    if (x.kind == NodeKind::symbol) {
        if (x.symbol.kind != y.symbol.kind) return x.symbol.kind < y.symbol.kind ? -1 : 1;
        return x.symbol.index < y.symbol.index ? -1 : (x.symbol.index > y.symbol.index ? 1 : 0);
    }
    if (x.kind == NodeKind::number) return x.value < y.value ? -1 : (x.value > y.value ? 1 : 0);
    if (int c = compare_u64(x.hash, y.hash)) return c;
    if (x.function != y.function) return x.function < y.function ? -1 : 1;
    if (int c = compare_u64(bits_of(x.value), bits_of(y.value))) return c;
    if (x.operand_count != y.operand_count) return x.operand_count < y.operand_count ? -1 : 1;
    const OperandSpan xs = operands(a), ys = operands(b);
    for (std::size_t i = 0; i < xs.size(); ++i) {
        if (int c = compare(xs[i].node, ys[i].node)) return c;
        if (int c = compare_u64(bits_of(xs[i].weight), bits_of(ys[i].weight))) return c;
    }
    return 0; // unreachable: equal content is interned once
}

void Graph::sort_and_merge(std::vector<Operand>& operands) const {
    std::sort(operands.begin(), operands.end(),
              [this](const Operand& a, const Operand& b) { return compare(a.node, b.node) < 0; });
    std::vector<Operand> merged;
    merged.reserve(operands.size());
    for (const Operand& op : operands) {
        if (!merged.empty() && merged.back().node == op.node)
            merged.back().weight += op.weight;
        else
            merged.push_back(op);
    }
    merged.erase(std::remove_if(merged.begin(), merged.end(),
                                [](const Operand& op) { return op.weight == 0.0; }),
                 merged.end());
    operands = std::move(merged);
}

NodeId Graph::number(double value) {
    Node n;
    n.kind = NodeKind::number;
    n.value = value;
    return intern(n, {});
}

NodeId Graph::symbol(SymbolRef ref) {
    Node n;
    n.kind = NodeKind::symbol;
    n.symbol = ref;
    return intern(n, {});
}

NodeId Graph::add(std::vector<Operand> terms, double constant) {
    std::vector<Operand> kept;
    kept.reserve(terms.size());
    for (const Operand& term : terms) {
        if (term.weight == 0.0) continue;
        const NodeKind kind = nodes_[term.node].kind;
        const double value = nodes_[term.node].value;
        if (kind == NodeKind::number) {
            constant += term.weight * value;
        } else if (kind == NodeKind::mul && value != 1.0) {
            kept.push_back({mul(operand_copy(term.node), 1.0), term.weight * value});
        } else {
            kept.push_back(term);
        }
    }
    sort_and_merge(kept);
    if (kept.empty()) return number(constant);
    if (kept.size() == 1 && constant == 0.0) {
        // w * x is a product, whatever built it: one normal form for one value.
        if (kept[0].weight == 1.0) return kept[0].node;
        if (nodes_[kept[0].node].kind == NodeKind::mul) {
            return mul(operand_copy(kept[0].node), nodes_[kept[0].node].value * kept[0].weight);
        }
        return mul({{kept[0].node, 1.0}}, kept[0].weight);
    }
    // x*(a - b) and -x*(b - a) are one value: the first term of a sum (in the
    // canonical order) always has a positive weight, the sign goes outside.
    const bool negated = kept[0].weight < 0.0;
    if (negated) {
        for (Operand& term : kept) term.weight = -term.weight;
        constant = -constant;
    }
    Node n;
    n.kind = NodeKind::add;
    n.value = constant;
    const NodeId sum = intern(n, kept);
    return negated ? mul({{sum, 1.0}}, -1.0) : sum;
}

NodeId Graph::mul(std::vector<Operand> factors, double coefficient) {
    std::vector<Operand> kept;
    kept.reserve(factors.size());
    for (const Operand& factor : factors) {
        if (factor.weight == 0.0) continue;
        const Node& f = nodes_[factor.node];
        const bool integer_power = factor.weight == std::floor(factor.weight);
        if (f.kind == NodeKind::number && integer_power) {
            coefficient *= std::pow(f.value, factor.weight);
        } else if (f.kind == NodeKind::mul && integer_power) {
            // (c * prod f_i^e_i)^w: products nest only through the sign of sums.
            coefficient *= std::pow(f.value, factor.weight);
            for (const Operand& inner : operands(factor.node))
                kept.push_back({inner.node, inner.weight * factor.weight});
        } else {
            kept.push_back(factor);
        }
    }
    if (coefficient == 0.0) return number(0.0);
    sort_and_merge(kept);
    // Powers that are not written as repeated multiplication become calls.
    bool converted = false;
    for (Operand& factor : kept) {
        if (is_small_integer(factor.weight, max_multiplied_power_)) continue;
        const double magnitude = std::fabs(factor.weight);
        const NodeId call_node = magnitude == 0.5
                                     ? call(Function::sqrt, {factor.node})
                                     : call(Function::pow, {factor.node, number(magnitude)});
        factor = {call_node, factor.weight < 0.0 ? -1.0 : 1.0};
        converted = true;
    }
    if (converted) sort_and_merge(kept);
    if (kept.empty()) return number(coefficient);
    if (kept.size() == 1 && kept[0].weight == 1.0 && coefficient == 1.0) return kept[0].node;
    Node n;
    n.kind = NodeKind::mul;
    n.value = coefficient;
    return intern(n, kept);
}

NodeId Graph::call(Function f, const std::vector<NodeId>& arguments) {
    Node n;
    n.kind = NodeKind::call;
    n.function = f;
    std::vector<Operand> operands;
    for (NodeId a : arguments) operands.push_back({a, 1.0});
    return intern(n, operands);
}

NodeId Graph::power(NodeId base, NodeId exponent) {
    if (nodes_[exponent].kind == NodeKind::number)
        return mul({{base, nodes_[exponent].value}}, 1.0);
    return call(Function::pow, {base, exponent});
}

} // namespace yamsc::ir
