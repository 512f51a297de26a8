#include "symbolic/approx.hpp"

#include <cmath>
#include <map>
#include <string>

namespace yamsc::symbolic {

using namespace GiNaC;

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

const char* function_name(TapeFunction f) {
    switch (f) {
    case TapeFunction::sin:
        return "sin";
    case TapeFunction::cos:
        return "cos";
    case TapeFunction::tan:
        return "tan";
    case TapeFunction::asin:
        return "asin";
    case TapeFunction::acos:
        return "acos";
    case TapeFunction::atan:
        return "atan";
    case TapeFunction::atan2:
        return "atan2";
    case TapeFunction::sinh:
        return "sinh";
    case TapeFunction::cosh:
        return "cosh";
    case TapeFunction::tanh:
        return "tanh";
    case TapeFunction::asinh:
        return "asinh";
    case TapeFunction::acosh:
        return "acosh";
    case TapeFunction::atanh:
        return "atanh";
    case TapeFunction::exp:
        return "exp";
    case TapeFunction::log:
        return "log";
    case TapeFunction::abs:
        return "abs";
    case TapeFunction::sqrt: // the Tape writes powers as products, never these
    case TapeFunction::pow:
        return ir::info(f).name.data();
    }
    return "?";
}

} // namespace

TaylorExpansion::TaylorExpansion(std::vector<symbol> symbols, int order)
    : group_size_(symbols.size()), order_(order) {
    std::vector<symbol> variables = symbols;
    const symbol placeholder("taylor_placeholder");
    variables.push_back(placeholder);
    placeholder_ = symbols.size();
    tape_ = std::make_unique<Tape>(variables);
    placeholder_node_ = tape_->import(placeholder);
    std::vector<TapeId> symbol_nodes;
    for (const symbol& s : symbols) symbol_nodes.push_back(tape_->import(s));

    monomials_ = monomials_up_to(group_size_, order_);
    std::map<std::vector<int>, int> index;
    for (std::size_t k = 0; k < monomials_.size(); ++k) {
        index[monomials_[k]] = static_cast<int>(k);
        int d = 0;
        std::vector<TapeTerm> factors;
        for (std::size_t i = 0; i < group_size_; ++i) {
            d += monomials_[k][i];
            if (monomials_[k][i] > 0)
                factors.push_back({symbol_nodes[i], static_cast<double>(monomials_[k][i])});
        }
        degree_.push_back(d);
        monomial_values_.push_back(tape_->mul(std::move(factors)));
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

ex TaylorExpansion::operator()(const ex& e) {
    const Series s = series(tape_->import(e));
    std::vector<TapeTerm> terms;
    for (std::size_t k = 0; k < s.size(); ++k)
        if (s[k] != tape_->zero()) terms.push_back({times(s[k], monomial_values_[k]), 1.0});
    return tape_->to_ginac(sum(terms));
}

bool TaylorExpansion::depends(TapeId node) const {
    for (std::size_t v = 0; v < group_size_; ++v)
        if (tape_->depends(node, v)) return true;
    return false;
}

TapeId TaylorExpansion::times(TapeId a, TapeId b) {
    return tape_->mul({{a, 1.0}, {b, 1.0}});
}

TapeId TaylorExpansion::call(TapeFunction f, TapeId argument) {
    // At a number (the usual expansion point 0) the value is a number: sin(0) = 0
    // must vanish, not stay a call.
    if (tape_->kind(argument) == TapeKind::number) {
        const double v = evaluate(f, tape_->value(argument));
        if (std::isfinite(v)) return tape_->number(v);
    }
    return tape_->call(f, {argument});
}

TapeId TaylorExpansion::sum(const std::vector<TapeTerm>& terms) {
    return tape_->add(terms);
}

TaylorExpansion::Series TaylorExpansion::series(TapeId node) {
    if (!depends(node)) return constant(node);
    if (auto it = memo_.find(node); it != memo_.end()) return it->second;
    Series s = compute(node);
    return memo_.emplace(node, std::move(s)).first->second;
}

TaylorExpansion::Series TaylorExpansion::constant(TapeId c) const {
    Series s(monomials_.size(), tape_->zero());
    s[0] = c;
    return s;
}

TaylorExpansion::Series TaylorExpansion::add_to(Series a, const Series& b, double weight) {
    for (std::size_t k = 0; k < a.size(); ++k)
        if (b[k] != tape_->zero()) a[k] = tape_->add({{a[k], 1.0}, {b[k], weight}});
    return a;
}

TaylorExpansion::Series TaylorExpansion::scale(const Series& a, TapeId c) {
    Series out(a.size(), tape_->zero());
    for (std::size_t k = 0; k < a.size(); ++k)
        if (a[k] != tape_->zero()) out[k] = times(a[k], c);
    return out;
}

TaylorExpansion::Series TaylorExpansion::multiply(const Series& a, const Series& b) {
    const std::size_t T = a.size();
    std::vector<std::vector<TapeTerm>> terms(T);
    for (std::size_t i = 0; i < T; ++i) {
        if (a[i] == tape_->zero()) continue;
        for (std::size_t j = 0; j < T; ++j) {
            const int k = product_index_[i][j];
            if (k < 0 || b[j] == tape_->zero()) continue;
            terms[static_cast<std::size_t>(k)].push_back({times(a[i], b[j]), 1.0});
        }
    }
    Series out(T);
    for (std::size_t k = 0; k < T; ++k) out[k] = sum(terms[k]);
    return out;
}

TaylorExpansion::Series TaylorExpansion::compose(const std::vector<TapeId>& c, const Series& r) {
    Series out = constant(c[0]);
    Series r_k = constant(tape_->one());
    for (int k = 1; k <= order_; ++k) {
        r_k = multiply(r_k, r); // starts at degree k: r has no constant term
        const TapeId ck = c[static_cast<std::size_t>(k)];
        if (ck != tape_->zero()) out = add_to(std::move(out), scale(r_k, ck));
    }
    return out;
}

TaylorExpansion::Series TaylorExpansion::compute(TapeId node) {
    Tape& t = *tape_;
    // A copy: new nodes may move the tape's operand storage.
    const std::vector<TapeTerm> ops(t.operands(node), t.operands(node) + t.operand_count(node));
    switch (t.kind(node)) {
    case TapeKind::number:
        return constant(node);
    case TapeKind::symbol: {
        Series s = constant(t.zero());
        s[1 + static_cast<std::size_t>(t.variable_of(node))] = t.one();
        return s;
    }
    case TapeKind::add: {
        std::vector<std::vector<TapeTerm>> terms(monomials_.size());
        terms[0].push_back({t.number(t.value(node)), 1.0});
        for (const TapeTerm& op : ops) {
            const Series s = series(op.node);
            for (std::size_t k = 0; k < s.size(); ++k)
                if (s[k] != t.zero()) terms[k].push_back({s[k], op.weight});
        }
        Series out(monomials_.size());
        for (std::size_t k = 0; k < out.size(); ++k) out[k] = sum(terms[k]);
        return out;
    }
    case TapeKind::mul: {
        // Factors without the group's symbols multiply the result once, at the end.
        std::vector<TapeTerm> independent;
        Series out = constant(t.one());
        for (const TapeTerm& f : ops) {
            if (!depends(f.node))
                independent.push_back(f);
            else if (f.weight == 1.0)
                out = multiply(out, series(f.node));
            else
                out = multiply(out, power(series(f.node), t.number(f.weight)));
        }
        return scale(out, t.mul(std::move(independent), t.value(node)));
    }
    case TapeKind::power: {
        const TapeId base = ops[0].node, exponent = ops[1].node;
        if (depends(exponent))
            throw NotExpandable("a power whose exponent depends on the approximated symbols", true);
        return power(series(base), exponent);
    }
    case TapeKind::call:
        return function(node);
    }
    throw diag::InternalError("approx: unknown tape node");
}

TaylorExpansion::Series TaylorExpansion::power(const Series& s, TapeId exponent) {
    Tape& t = *tape_;
    if (t.kind(exponent) == TapeKind::number && is_whole(t.value(exponent))) {
        auto n = static_cast<long>(t.value(exponent));
        Series out = constant(t.one()), square = s;
        while (n > 0) { // binary powering; every product is truncated
            if (n & 1) out = multiply(out, square);
            n >>= 1;
            if (n > 0) square = multiply(square, square);
        }
        return out;
    }
    // (b0 + r)^α = b0^α Σ binom(α, k) (r / b0)^k
    const TapeId b0 = s[0];
    if (b0 == t.zero())
        throw NotExpandable("a division by (or a root of) an expression that is zero when the "
                            "approximated symbols are",
                            false);
    Series r = scale(s, t.mul({{b0, -1.0}}));
    r[0] = t.zero();
    std::vector<TapeId> c{t.one()};
    for (int k = 1; k <= order_; ++k) {
        const TapeId alpha_minus = t.add({{exponent, 1.0}}, -(k - 1.0));
        c.push_back(t.mul({{c.back(), 1.0}, {alpha_minus, 1.0}}, 1.0 / k));
    }
    return scale(compose(c, r), t.power(b0, exponent));
}

TaylorExpansion::Series TaylorExpansion::function(TapeId node) {
    Tape& t = *tape_;
    const TapeFunction f = t.function(node);
    if (f == TapeFunction::atan2 || f == TapeFunction::abs)
        throw NotExpandable(
            std::string("the function ") + function_name(f) + " of the approximated symbols", true);
    Series r = series(t.operands(node)[0].node);
    const TapeId a0 = r[0];
    r[0] = t.zero();
    return compose(derivatives_at(f, a0), r);
}

std::vector<TapeId> TaylorExpansion::derivatives_at(TapeFunction f, TapeId a0) {
    Tape& t = *tape_;
    std::vector<TapeId> c;
    double factorial = 1;
    if (f == TapeFunction::sin || f == TapeFunction::cos) {
        // The derivatives cycle through sin, cos, -sin, -cos.
        const TapeId s = call(TapeFunction::sin, a0), co = call(TapeFunction::cos, a0);
        const TapeId cycle[4] = {s, co, s, co};
        const double sign[4] = {1, 1, -1, -1};
        const int shift = f == TapeFunction::sin ? 0 : 1;
        for (int k = 0; k <= order_; ++k) {
            if (k > 0) factorial *= k;
            const int i = (k + shift) % 4;
            c.push_back(t.mul({{cycle[i], 1.0}}, sign[i] / factorial));
        }
        return c;
    }
    // f^(k)(x) at a placeholder variable x, then x = a0.
    TapeId g = t.call(f, {placeholder_node_});
    ForwardDerivative d(t, placeholder_);
    for (int k = 0; k <= order_; ++k) {
        if (k > 0) {
            factorial *= k;
            g = d(g);
        }
        std::unordered_map<TapeId, TapeId> memo;
        c.push_back(t.mul({{substitute_placeholder(g, a0, memo), 1.0}}, 1.0 / factorial));
    }
    return c;
}

TapeId TaylorExpansion::substitute_placeholder(TapeId node, TapeId value,
                                               std::unordered_map<TapeId, TapeId>& memo) {
    Tape& t = *tape_;
    if (!t.depends(node, placeholder_)) return node;
    if (auto it = memo.find(node); it != memo.end()) return it->second;
    const std::vector<TapeTerm> ops(t.operands(node), t.operands(node) + t.operand_count(node));
    std::vector<TapeTerm> mapped;
    for (const TapeTerm& o : ops)
        mapped.push_back({substitute_placeholder(o.node, value, memo), o.weight});
    TapeId out = node;
    switch (t.kind(node)) {
    case TapeKind::symbol:
        out = value;
        break;
    case TapeKind::add:
        out = t.add(std::move(mapped), t.value(node));
        break;
    case TapeKind::mul:
        out = t.mul(std::move(mapped), t.value(node));
        break;
    case TapeKind::power:
        out = t.power(mapped[0].node, mapped[1].node);
        break;
    case TapeKind::call: {
        std::vector<TapeId> args;
        for (const TapeTerm& m : mapped) args.push_back(m.node);
        out = args.size() == 1 ? call(t.function(node), args[0])
                               : t.call(t.function(node), std::move(args));
        break;
    }
    case TapeKind::number:
        break;
    }
    return memo.emplace(node, out).first->second;
}

bool approximate(const model::Model& m, Equations& eq, diag::Diagnostics& diags) {
    // The first channel of each input (its derivatives are channels of their own).
    std::vector<std::size_t> first_channel;
    std::size_t channel = 0;
    for (const model::Input& in : m.inputs) {
        first_channel.push_back(channel);
        channel += static_cast<std::size_t>(in.order) + 1;
    }
    for (const model::Approximation& group : m.approximations) {
        std::vector<symbol> symbols;
        std::string names;
        for (const auto& s : group.symbols) {
            const auto i = static_cast<std::size_t>(s.index);
            names += (names.empty() ? "" : ", ") + s.name;
            if (s.kind == model::NameKind::param)
                symbols.push_back(eq.params.at(i).sym);
            else if (s.kind == model::NameKind::dof)
                symbols.push_back(eq.dofs.at(i).q);
            else
                symbols.push_back(eq.inputs.at(first_channel.at(i)).sym);
        }
        TaylorExpansion expand(symbols, group.order);
        try {
            for (Row& row : eq.M)
                for (ex& e : row) e = expand(e);
            for (ex& e : eq.F) e = expand(e);
        } catch (const NotExpandable& x) {
            diags.error(x.not_supported ? diag::Kind::NotSupported : diag::Kind::InvalidValue,
                        group.loc,
                        "approx: cannot expand the equations in " + names + " to order " +
                            std::to_string(group.order) + ": they contain " + x.what());
            return false;
        }
    }
    return true;
}

} // namespace yamsc::symbolic
