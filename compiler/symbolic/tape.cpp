#include "symbolic/tape.hpp"

#include "diag/diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <string_view>

namespace yamsc::symbolic {

using namespace GiNaC;

namespace {

// The pairs of a GiNaC sum or product and its numeric part, read in place: op(i)
// would build a new object for every pair with a coefficient. A pointer to a
// protected member formed in a derived class may be applied to any object of the
// base class; writing through it builds a sum or product from given pairs
// without the constructors' flattening, sorting and evaluation.
struct SeqAccess : expairseq {
    static const epvector& pairs(const expairseq& e) { return e.*(&SeqAccess::seq); }
    static const ex& numeric_part(const expairseq& e) { return e.*(&SeqAccess::overall_coeff); }
    static void set(expairseq& e, epvector pairs, const ex& numeric_part) {
        e.*(&SeqAccess::seq) = std::move(pairs);
        e.*(&SeqAccess::overall_coeff) = numeric_part;
    }
};

double real(const ex& e) {
    const numeric& n = ex_to<numeric>(e);
    if (!n.is_real()) throw diag::InternalError("cannot differentiate a complex number");
    return n.to_double();
}

std::uint64_t bits_of(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

std::uint64_t combine(std::uint64_t h, std::uint64_t v) {
    return mix(h ^ mix(v));
}

/// A GiNaC number for a weight: exact integers (and halves) stay exact.
ex number_ex(double v) {
    if (v == std::floor(v) && std::fabs(v) < 1e15) return numeric(static_cast<long>(v));
    if (2 * v == std::floor(2 * v) && std::fabs(v) < 1e15)
        return numeric(static_cast<long>(2 * v), 2);
    return numeric(v);
}

bool is_small_integer(double w) {
    return w == std::floor(w) && std::fabs(w) < 64.0;
}

} // namespace

// ---- construction ---------------------------------------------------------------------

Tape::Tape(const std::vector<symbol>& variables)
    : variable_count_(variables.size()), words_((variables.size() + 63) / 64 + 1) {
    for (std::size_t i = 0; i < variables.size(); ++i) {
        ex s = variables[i]; // a copy: comparisons re-point handles (see dag.cpp)
        symbol_index_.emplace(s, std::make_pair(static_cast<std::int32_t>(symbols_.size()),
                                                static_cast<std::int32_t>(i)));
        symbols_.push_back(s);
    }
    zero_ = number(0.0);
    one_ = number(1.0);
}

bool Tape::same(TapeId id, const Node& n, const std::vector<TapeTerm>& operands) const {
    const Node& a = nodes_[id];
    if (a.hash != n.hash || a.kind != n.kind || a.function != n.function || a.symbol != n.symbol ||
        bits_of(a.value) != bits_of(n.value) || a.count != operands.size())
        return false;
    const TapeTerm* mine = terms_.data() + a.first;
    for (std::size_t i = 0; i < operands.size(); ++i)
        if (mine[i].node != operands[i].node ||
            bits_of(mine[i].weight) != bits_of(operands[i].weight))
            return false;
    return true;
}

void Tape::grow_table() {
    table_.assign(table_.empty() ? 4096 : 2 * table_.size(), ~TapeId{0});
    const std::size_t mask = table_.size() - 1;
    for (TapeId id = 0; id < nodes_.size(); ++id) {
        std::size_t slot = nodes_[id].hash & mask;
        while (table_[slot] != ~TapeId{0}) slot = (slot + 1) & mask;
        table_[slot] = id;
    }
}

TapeId Tape::intern(Node n, const std::vector<TapeTerm>& operands) {
    if (n.value == 0.0) n.value = 0.0; // no -0.0
    std::uint64_t h = mix(static_cast<std::uint64_t>(n.kind) + 1);
    h = combine(h, static_cast<std::uint64_t>(n.function));
    h = combine(h, static_cast<std::uint64_t>(static_cast<std::uint32_t>(n.symbol)));
    h = combine(h, bits_of(n.value));
    for (const TapeTerm& t : operands) {
        h = combine(h, nodes_[t.node].hash);
        h = combine(h, bits_of(t.weight));
    }
    n.hash = h;
    if (2 * (nodes_.size() + 1) > table_.size()) grow_table();
    const std::size_t mask = table_.size() - 1;
    std::size_t slot = h & mask;
    for (; table_[slot] != ~TapeId{0}; slot = (slot + 1) & mask)
        if (same(table_[slot], n, operands)) return table_[slot];

    const auto id = static_cast<TapeId>(nodes_.size());
    n.first = static_cast<std::uint32_t>(terms_.size());
    n.count = static_cast<std::uint32_t>(operands.size());
    terms_.insert(terms_.end(), operands.begin(), operands.end());
    nodes_.push_back(n);
    table_[slot] = id;
    // Dependence: the variable itself, or the union over the operands.
    deps_.resize(deps_.size() + words_, 0);
    std::uint64_t* mine = deps_.data() + static_cast<std::size_t>(id) * words_;
    if (n.variable >= 0) mine[n.variable / 64] |= std::uint64_t{1} << (n.variable % 64);
    for (const TapeTerm& t : operands) {
        const std::uint64_t* theirs = deps_.data() + static_cast<std::size_t>(t.node) * words_;
        for (std::size_t w = 0; w < words_; ++w) mine[w] |= theirs[w];
    }
    return id;
}

TapeId Tape::number(double value) {
    Node n;
    n.kind = TapeKind::number;
    n.value = value;
    return intern(n, {});
}

namespace {

/// Sorts by node id and merges repeated operands (adding their weights).
void sort_and_merge(std::vector<TapeTerm>& v) {
    std::sort(v.begin(), v.end(),
              [](const TapeTerm& a, const TapeTerm& b) { return a.node < b.node; });
    std::size_t out = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (out > 0 && v[out - 1].node == v[i].node)
            v[out - 1].weight += v[i].weight;
        else
            v[out++] = v[i];
    }
    v.resize(out);
    v.erase(std::remove_if(v.begin(), v.end(), [](const TapeTerm& t) { return t.weight == 0.0; }),
            v.end());
}

} // namespace

TapeId Tape::add(std::vector<TapeTerm> terms, double constant) {
    std::size_t out = 0;
    for (const TapeTerm& t : terms) {
        if (t.weight == 0.0) continue;
        if (nodes_[t.node].kind == TapeKind::number) {
            constant += t.weight * nodes_[t.node].value;
            continue;
        }
        terms[out++] = t;
    }
    terms.resize(out);
    sort_and_merge(terms);
    if (terms.empty()) return number(constant);
    if (terms.size() == 1 && constant == 0.0) {
        // w * x is a product: its factors with the coefficient scaled.
        const TapeTerm only = terms[0];
        if (only.weight == 1.0) return only.node;
        const Node& node = nodes_[only.node];
        if (node.kind == TapeKind::mul) {
            std::vector<TapeTerm> factors(terms_.begin() + node.first,
                                          terms_.begin() + node.first + node.count);
            return mul(std::move(factors), node.value * only.weight);
        }
        return mul({{only.node, 1.0}}, only.weight);
    }
    Node n;
    n.kind = TapeKind::add;
    n.value = constant;
    return intern(n, terms);
}

TapeId Tape::mul(std::vector<TapeTerm> factors, double coefficient) {
    std::size_t out = 0;
    for (const TapeTerm& f : factors) {
        if (f.weight == 0.0) continue;
        const Node& node = nodes_[f.node];
        if (node.kind == TapeKind::number && is_small_integer(f.weight)) {
            coefficient *= std::pow(node.value, f.weight);
            continue;
        }
        // A product of one factor of exponent 1 is that factor with its coefficient.
        if (node.kind == TapeKind::mul && node.count == 1 && f.weight == 1.0) {
            coefficient *= node.value;
            factors[out++] = terms_[node.first];
            continue;
        }
        factors[out++] = f;
    }
    factors.resize(out);
    if (coefficient == 0.0) return zero_;
    sort_and_merge(factors);
    if (factors.empty()) return number(coefficient);
    if (factors.size() == 1 && factors[0].weight == 1.0 && coefficient == 1.0)
        return factors[0].node;
    Node n;
    n.kind = TapeKind::mul;
    n.value = coefficient;
    return intern(n, factors);
}

TapeId Tape::power(TapeId base, TapeId exponent) {
    if (nodes_[exponent].kind == TapeKind::number)
        return mul({{base, nodes_[exponent].value}}, 1.0);
    Node n;
    n.kind = TapeKind::power;
    return intern(n, {{base, 1.0}, {exponent, 1.0}});
}

TapeId Tape::call(TapeFunction f, std::vector<TapeId> arguments) {
    Node n;
    n.kind = TapeKind::call;
    n.function = f;
    std::vector<TapeTerm> operands;
    for (TapeId a : arguments) operands.push_back({a, 1.0});
    return intern(n, operands);
}

// ---- import ------------------------------------------------------------------------------

TapeId Tape::symbol_node(const ex& s) {
    auto it = symbol_index_.find(ex(s)); // a copy: see the constructor
    if (it == symbol_index_.end()) {
        const auto index = static_cast<std::int32_t>(symbols_.size());
        it = symbol_index_.emplace(ex(s), std::make_pair(index, std::int32_t{-1})).first;
        symbols_.push_back(s);
    }
    Node n;
    n.kind = TapeKind::symbol;
    n.symbol = it->second.first;
    n.variable = it->second.second;
    return intern(n, {});
}

TapeId Tape::import_leaf(const ex& e) {
    if (is_a<numeric>(e)) return number(real(e));
    if (is_a<constant>(e)) {
        const ex value = ex_to<constant>(e).evalf();
        if (!is_a<numeric>(value)) throw diag::InternalError("a constant without a value");
        return number(real(value));
    }
    return symbol_node(e);
}

TapeId Tape::import(const ex& root) {
    // Each frame: a GiNaC node and its operands (with weights) still to import.
    struct Frame {
        ex e;
        std::vector<std::pair<ex, double>> operands;
        std::size_t next = 0;
        double scalar = 0.0;
        bool expanded = false;
    };
    auto known = [this](const ex& e) -> const TapeId* {
        auto it = imported_.find(&ex_to<basic>(e));
        return it == imported_.end() ? nullptr : &it->second.second;
    };
    auto remember = [this](const ex& e, TapeId id) {
        imported_.emplace(&ex_to<basic>(e), std::make_pair(e, id));
        if (exported_.size() <= id) {
            exported_.resize(id + 1);
            has_export_.resize(id + 1, false);
        }
        if (!has_export_[id]) {
            exported_[id] = e;
            has_export_[id] = true;
        }
    };
    if (const TapeId* hit = known(root)) return *hit;
    std::vector<Frame> stack;
    stack.push_back(Frame{root, {}, 0, 0.0, false});
    while (!stack.empty()) {
        Frame& top = stack.back();
        if (!top.expanded) {
            if (known(top.e)) {
                stack.pop_back();
                continue;
            }
            const ex& e = top.e;
            if (is_a<numeric>(e) || is_a<constant>(e) || is_a<symbol>(e)) {
                remember(e, import_leaf(e));
                stack.pop_back();
                continue;
            }
            if (is_exactly_a<GiNaC::add>(e) || is_exactly_a<GiNaC::mul>(e)) {
                const auto& seq = ex_to<expairseq>(e);
                for (const expair& p : SeqAccess::pairs(seq))
                    top.operands.emplace_back(p.rest, real(p.coeff));
                top.scalar = real(SeqAccess::numeric_part(seq));
            } else if (is_exactly_a<GiNaC::power>(e) || is_a<GiNaC::function>(e)) {
                if (is_a<GiNaC::function>(e)) {
                    const std::string name = ex_to<GiNaC::function>(e).get_name();
                    if (!ir::model_function(name, e.nops()))
                        throw diag::InternalError("cannot differentiate function " + name);
                }
                for (std::size_t i = 0; i < e.nops(); ++i) top.operands.emplace_back(e.op(i), 1.0);
            } else {
                throw diag::InternalError("cannot differentiate expression node of class " +
                                          std::string(ex_to<basic>(e).class_name()));
            }
            top.expanded = true;
        }
        if (top.next < top.operands.size()) {
            ex operand = top.operands[top.next++].first; // push_back may move `top`
            if (!known(operand)) stack.push_back(Frame{std::move(operand), {}, 0, 0.0, false});
            continue;
        }
        std::vector<TapeTerm> terms;
        for (const auto& [operand, weight] : top.operands)
            terms.push_back({*known(operand), weight});
        const ex& e = top.e;
        TapeId id;
        if (is_exactly_a<GiNaC::add>(e)) {
            id = add(std::move(terms), top.scalar);
        } else if (is_exactly_a<GiNaC::mul>(e)) {
            id = mul(std::move(terms), top.scalar);
        } else if (is_exactly_a<GiNaC::power>(e)) {
            id = power(terms[0].node, terms[1].node);
        } else {
            const std::string name = ex_to<GiNaC::function>(e).get_name();
            std::vector<TapeId> arguments;
            for (const TapeTerm& t : terms) arguments.push_back(t.node);
            const auto f = ir::model_function(name, arguments.size()); // checked above
            id = call(*f, std::move(arguments));
        }
        remember(e, id);
        stack.pop_back();
    }
    return *known(root);
}

// ---- export ------------------------------------------------------------------------------

GiNaC::ex Tape::build_ginac(TapeId id) {
    const Node& n = nodes_[id];
    const TapeTerm* ops = terms_.data() + n.first;
    switch (n.kind) {
    case TapeKind::number:
        return number_ex(n.value);
    case TapeKind::symbol:
        return symbols_[static_cast<std::size_t>(n.symbol)];
    case TapeKind::add:
    case TapeKind::mul: {
        epvector pairs;
        pairs.reserve(n.count);
        for (std::uint32_t i = 0; i < n.count; ++i)
            pairs.emplace_back(exported_[ops[i].node], number_ex(ops[i].weight));
        expairseq& seq = n.kind == TapeKind::add
                             ? static_cast<expairseq&>(dynallocate<GiNaC::add>())
                             : static_cast<expairseq&>(dynallocate<GiNaC::mul>());
        SeqAccess::set(seq, std::move(pairs), number_ex(n.value));
        // Evaluated: GiNaC must neither evaluate (it walks operand trees) nor
        // re-normalise what is built as intended.
        seq.setflag(status_flags::evaluated);
        return seq;
    }
    case TapeKind::power: {
        auto& p = dynallocate<GiNaC::power>(exported_[ops[0].node], exported_[ops[1].node]);
        p.setflag(status_flags::evaluated);
        return p;
    }
    case TapeKind::call: {
        const ir::FunctionInfo& f = ir::info(n.function);
        const unsigned serial = GiNaC::function::find_function(std::string(f.name), f.arity);
        exvector arguments;
        for (std::uint32_t i = 0; i < n.count; ++i) arguments.push_back(exported_[ops[i].node]);
        auto& call_node = dynallocate<GiNaC::function>(serial, std::move(arguments));
        call_node.setflag(status_flags::evaluated);
        return call_node;
    }
    }
    throw diag::InternalError("tape: unknown node kind");
}

GiNaC::ex Tape::to_ginac(TapeId root) {
    if (exported_.size() < nodes_.size()) {
        exported_.resize(nodes_.size());
        has_export_.resize(nodes_.size(), false);
    }
    if (has_export_[root]) return exported_[root];
    // Post-order over the operands not exported yet; ids are topological.
    std::vector<std::pair<TapeId, std::uint32_t>> stack{{root, 0}};
    while (!stack.empty()) {
        auto& [id, next] = stack.back();
        if (next < nodes_[id].count) {
            const TapeId child = terms_[nodes_[id].first + next++].node;
            if (!has_export_[child]) stack.emplace_back(child, 0);
            continue;
        }
        if (!has_export_[id]) {
            exported_[id] = build_ginac(id);
            has_export_[id] = true;
        }
        stack.pop_back();
    }
    return exported_[root];
}

// ---- forward-mode derivatives -------------------------------------------------------------

ForwardDerivative::ForwardDerivative(Tape& tape, std::size_t variable)
    : ForwardDerivative(tape, [&] {
          std::vector<TapeId> seeds(tape.variable_count(), tape.zero());
          seeds.at(variable) = tape.one();
          return seeds;
      }()) {}

ForwardDerivative::ForwardDerivative(Tape& tape, std::vector<TapeId> seeds)
    : tape_(tape), seeds_(std::move(seeds)), mask_(tape.dependence_words(), 0) {
    if (seeds_.size() != tape.variable_count())
        throw diag::InternalError("a directional derivative needs one seed per variable");
    for (std::size_t v = 0; v < seeds_.size(); ++v)
        if (seeds_[v] != tape.zero()) mask_[v / 64] |= std::uint64_t{1} << (v % 64);
}

TapeId ForwardDerivative::memo(TapeId node) const {
    if (!relevant(node)) return tape_.zero();
    return done_.at(node);
}

// d(node) from the derivatives of its operands (all in done_ already).
TapeId ForwardDerivative::rule(TapeId node) {
    Tape& t = tape_;
    const TapeTerm* ops = t.operands(node);
    const std::uint32_t count = t.operand_count(node);
    switch (t.kind(node)) {
    case TapeKind::number:
        return t.zero();
    case TapeKind::symbol:
        return t.variable_of(node) < 0 ? t.zero()
                                       : seeds_[static_cast<std::size_t>(t.variable_of(node))];
    case TapeKind::add: {
        std::vector<TapeTerm> terms;
        for (std::uint32_t i = 0; i < count; ++i) {
            const TapeId d = memo(ops[i].node);
            if (d != t.zero()) terms.push_back({d, ops[i].weight});
        }
        return t.add(std::move(terms));
    }
    case TapeKind::mul: {
        // d(c prod x_i^e_i) = sum_i c e_i x_i^(e_i - 1) dx_i prod_(j != i) x_j^e_j
        std::vector<TapeTerm> terms;
        const std::vector<TapeTerm> factors(ops, ops + count);
        const double coefficient = t.value(node);
        for (std::uint32_t i = 0; i < count; ++i) {
            const TapeId d = memo(factors[i].node);
            if (d == t.zero()) continue;
            std::vector<TapeTerm> product = factors;
            product[i].weight -= 1.0;
            product.push_back({d, 1.0});
            terms.push_back({t.mul(std::move(product), coefficient * factors[i].weight), 1.0});
        }
        return t.add(std::move(terms));
    }
    case TapeKind::power: {
        // d(b^x) = b^x (dx log b + x db / b)
        const TapeId b = ops[0].node, x = ops[1].node;
        const TapeId db = memo(b), dx = memo(x);
        std::vector<TapeTerm> inner;
        if (dx != t.zero())
            inner.push_back({t.mul({{dx, 1.0}, {t.call(TapeFunction::log, {b}), 1.0}}), 1.0});
        if (db != t.zero()) inner.push_back({t.mul({{x, 1.0}, {db, 1.0}, {b, -1.0}}), 1.0});
        return t.mul({{node, 1.0}, {t.add(std::move(inner)), 1.0}});
    }
    case TapeKind::call:
        break;
    }
    const TapeId a = ops[0].node;
    const TapeId da = memo(a);
    if (t.function(node) == TapeFunction::atan2) {
        // d atan2(y, x) = (x dy - y dx) / (x^2 + y^2)
        const TapeId y = a, x = ops[1].node, dy = da, dx = memo(ops[1].node);
        std::vector<TapeTerm> numerator;
        if (dy != t.zero()) numerator.push_back({t.mul({{x, 1.0}, {dy, 1.0}}), 1.0});
        if (dx != t.zero()) numerator.push_back({t.mul({{y, 1.0}, {dx, 1.0}}), -1.0});
        const TapeId denominator = t.add({{t.mul({{x, 2.0}}), 1.0}, {t.mul({{y, 2.0}}), 1.0}});
        return t.mul({{t.add(std::move(numerator)), 1.0}, {denominator, -1.0}});
    }
    if (da == t.zero()) return t.zero();
    const TapeId a2 = t.mul({{a, 2.0}});
    TapeId outer = t.zero();
    switch (t.function(node)) {
    case TapeFunction::sin:
        outer = t.call(TapeFunction::cos, {a});
        break;
    case TapeFunction::cos:
        outer = t.mul({{t.call(TapeFunction::sin, {a}), 1.0}}, -1.0);
        break;
    case TapeFunction::tan:
        outer = t.add({{t.mul({{node, 2.0}}), 1.0}}, 1.0);
        break;
    case TapeFunction::asin:
        outer = t.mul({{t.add({{a2, -1.0}}, 1.0), -0.5}});
        break;
    case TapeFunction::acos:
        outer = t.mul({{t.add({{a2, -1.0}}, 1.0), -0.5}}, -1.0);
        break;
    case TapeFunction::atan:
        outer = t.mul({{t.add({{a2, 1.0}}, 1.0), -1.0}});
        break;
    case TapeFunction::sinh:
        outer = t.call(TapeFunction::cosh, {a});
        break;
    case TapeFunction::cosh:
        outer = t.call(TapeFunction::sinh, {a});
        break;
    case TapeFunction::tanh:
        outer = t.add({{t.mul({{node, 2.0}}), -1.0}}, 1.0);
        break;
    case TapeFunction::asinh:
        outer = t.mul({{t.add({{a2, 1.0}}, 1.0), -0.5}});
        break;
    case TapeFunction::acosh:
        outer = t.mul({{t.add({{a2, 1.0}}, -1.0), -0.5}});
        break;
    case TapeFunction::atanh:
        outer = t.mul({{t.add({{a2, -1.0}}, 1.0), -1.0}});
        break;
    case TapeFunction::exp:
        outer = node;
        break;
    case TapeFunction::log:
        outer = t.mul({{a, -1.0}});
        break;
    case TapeFunction::abs:
        outer = t.mul({{a, 1.0}, {node, -1.0}});
        break;
    case TapeFunction::atan2:
    case TapeFunction::sqrt: // the Tape writes powers as products, never these
    case TapeFunction::pow:
        break;
    }
    return t.mul({{outer, 1.0}, {da, 1.0}});
}

TapeId ForwardDerivative::operator()(TapeId root) {
    if (!relevant(root)) return tape_.zero();
    if (auto it = done_.find(root); it != done_.end()) return it->second;
    // Post-order over the operands that depend on the variable and are not done.
    std::vector<std::pair<TapeId, std::uint32_t>> stack{{root, 0}};
    while (!stack.empty()) {
        auto& [id, next] = stack.back();
        if (next < tape_.operand_count(id)) {
            const TapeId child = tape_.operands(id)[next++].node;
            if (relevant(child) && done_.find(child) == done_.end()) stack.emplace_back(child, 0);
            continue;
        }
        const TapeId node = id;
        stack.pop_back();
        if (done_.find(node) == done_.end()) done_.emplace(node, rule(node));
    }
    return done_.at(root);
}

} // namespace yamsc::symbolic
