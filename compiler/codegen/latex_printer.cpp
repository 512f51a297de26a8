#include "codegen/latex_printer.hpp"

#include "diag/diagnostics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

namespace yamsc::codegen::latex {

using ir::Function;
using ir::NodeId;
using ir::NodeKind;

namespace {

const std::set<std::string>& greek() {
    static const std::set<std::string> names{
        "alpha", "beta",  "gamma",   "delta",    "epsilon",   "zeta",  "eta",     "theta",
        "iota",  "kappa", "lambda",  "mu",       "nu",        "xi",    "pi",      "rho",
        "sigma", "tau",   "upsilon", "phi",      "chi",       "psi",   "omega",   "Gamma",
        "Delta", "Theta", "Lambda",  "Xi",       "Pi",        "Sigma", "Upsilon", "Phi",
        "Psi",   "Omega", "varphi",  "vartheta", "varepsilon"};
    return names;
}

std::string base_name(const std::string& base) {
    if (greek().count(base)) return "\\" + base;
    if (base.size() == 1) return base;
    return "\\mathrm{" + escape_text(base) + "}";
}

std::string subscript_part(const std::string& part) {
    if (greek().count(part)) return "\\" + part;
    return escape_text(part);
}

const char* function_command(Function f) {
    switch (f) {
    case Function::sin:
        return "\\sin";
    case Function::cos:
        return "\\cos";
    case Function::tan:
        return "\\tan";
    case Function::asin:
        return "\\arcsin";
    case Function::acos:
        return "\\arccos";
    case Function::atan:
        return "\\arctan";
    case Function::atan2:
        return "\\operatorname{atan2}";
    case Function::sinh:
        return "\\sinh";
    case Function::cosh:
        return "\\cosh";
    case Function::tanh:
        return "\\tanh";
    case Function::asinh:
        return "\\operatorname{arsinh}";
    case Function::acosh:
        return "\\operatorname{arcosh}";
    case Function::atanh:
        return "\\operatorname{artanh}";
    case Function::exp:
        return "\\exp";
    case Function::log:
        return "\\ln";
    case Function::abs:
    case Function::sqrt: // printed as powers (Expander::compute)
    case Function::pow:
        return "";
    }
    return "";
}

bool is_integer(double x) {
    return std::floor(x) == x && std::fabs(x) < 1e6;
}

} // namespace

std::string escape_text(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '\\':
            out += "\\textbackslash{}";
            break;
        case '{':
        case '}':
        case '_':
        case '#':
        case '$':
        case '%':
        case '&':
            out += '\\';
            out += c;
            break;
        case '^':
            out += "\\^{}";
            break;
        case '~':
            out += "\\~{}";
            break;
        default:
            // Control characters never reach a document, nor bytes outside ASCII
            // (pdflatex without packages knows no glyph for them).
            if (static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f)
                out += c;
        }
    }
    return out;
}

std::string symbol_name(const std::string& name, int primes, const std::string& suffix) {
    const auto underscore = name.find('_');
    std::string base = underscore == std::string::npos ? name : name.substr(0, underscore);
    if (base.empty()) base = name; // `_x`: no base before the underscore
    std::string sub;
    if (underscore != std::string::npos && underscore > 0) {
        std::string rest = name.substr(underscore + 1), part;
        for (std::size_t i = 0; i <= rest.size(); ++i) {
            if (i == rest.size() || rest[i] == '_') {
                if (!part.empty()) sub += (sub.empty() ? "" : ",") + subscript_part(part);
                part.clear();
            } else {
                part += rest[i];
            }
        }
    }
    // Trailing digits of the base are an index: L1 -> L_{1}, theta12 -> \theta_{12}.
    std::size_t digits = base.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(base[digits - 1]))) --digits;
    if (digits > 0 && digits < base.size()) {
        sub = base.substr(digits) + (sub.empty() ? "" : "," + sub);
        base.resize(digits);
    }
    if (!suffix.empty()) sub += (sub.empty() ? "" : ",") + suffix;
    std::string out = base_name(base);
    if (primes == 1) out = "\\dot{" + out + "}";
    if (primes >= 2) out = "\\ddot{" + out + "}";
    if (!sub.empty()) out += "_{" + sub + "}";
    return out;
}

std::string number(double value) {
    if (value == 0) return "0";
    std::string s = fmt::format("{:.6g}", value);
    const auto e = s.find('e');
    if (e == std::string::npos) return s;
    const std::string mantissa = s.substr(0, e);
    const int exponent = std::stoi(s.substr(e + 1));
    return (mantissa == "1"    ? std::string()
            : mantissa == "-1" ? "-"
                               : mantissa + "\\cdot ") +
           "10^{" + std::to_string(exponent) + "}";
}

Expander::Expander(const ir::Graph& graph, std::size_t max_terms)
    : graph_(graph), max_terms_(max_terms) {}

void Expander::name(ir::SymbolRef s, std::string latex, int rank) {
    rank_[latex] = rank;
    names_[key(s)] = std::move(latex);
}

void Expander::substitute(ir::SymbolRef s, NodeId value) {
    Poly p = poly(value);
    memo_.clear(); // earlier expansions used the symbol itself
    substituted_[key(s)] = std::move(p);
}

void Expander::substitute(ir::SymbolRef s, double value) {
    memo_.clear();
    substituted_[key(s)] = value == 0 ? Poly{} : Poly{{Monomial{}, value}};
}

std::vector<std::string> Expander::terms(const std::vector<ir::Operand>& combination) {
    std::vector<Poly> polys;
    for (const ir::Operand& op : combination) polys.push_back(poly(op.node));
    std::vector<std::pair<const Poly*, double>> parts;
    for (std::size_t i = 0; i < polys.size(); ++i)
        parts.push_back({&polys[i], combination[i].weight});
    return print_terms(parts.size() == 1 && parts[0].second == 1.0 ? polys[0] : sum(parts));
}

const Expander::Poly& Expander::poly(NodeId node) {
    if (auto it = memo_.find(node); it != memo_.end()) return it->second;
    Poly p = compute(node);
    if (p.size() > max_terms_)
        throw TooLong("more than " + std::to_string(max_terms_) + " terms when expanded");
    return memo_.emplace(node, std::move(p)).first->second;
}

Expander::Poly Expander::atom(const std::string& text, int exponent) const {
    return Poly{{Monomial{{text, exponent}}, 1.0}};
}

Expander::Poly Expander::compute(NodeId node) {
    const ir::Node& n = graph_.node(node);
    const ir::OperandSpan ops = graph_.operands(node);
    switch (n.kind) {
    case NodeKind::number:
        return n.value == 0 ? Poly{} : Poly{{Monomial{}, n.value}};
    case NodeKind::symbol: {
        if (auto it = substituted_.find(key(n.symbol)); it != substituted_.end()) return it->second;
        auto it = names_.find(key(n.symbol));
        if (it == names_.end()) throw diag::InternalError("latex: a symbol without a name");
        return atom(it->second);
    }
    case NodeKind::add: {
        std::vector<Poly> polys;
        for (const ir::Operand& op : ops) polys.push_back(poly(op.node));
        const Poly constant = n.value == 0 ? Poly{} : Poly{{Monomial{}, n.value}};
        std::vector<std::pair<const Poly*, double>> parts{{&constant, 1.0}};
        for (std::size_t i = 0; i < ops.size(); ++i) parts.push_back({&polys[i], ops[i].weight});
        return sum(parts);
    }
    case NodeKind::mul: {
        // Factors in the order of their printed form: the rounding of the
        // coefficients does not depend on the operand order.
        std::vector<std::pair<std::string, Poly>> factors;
        for (const ir::Operand& op : ops) {
            Poly f = power(poly(op.node), op.weight);
            factors.emplace_back(print(f), std::move(f));
        }
        std::sort(factors.begin(), factors.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        Poly out{{Monomial{}, n.value}};
        for (const auto& f : factors) out = product(out, f.second);
        return out;
    }
    case NodeKind::call: {
        const Function f = n.function;
        std::vector<Poly> args;
        bool constant = true;
        for (const ir::Operand& op : ops) {
            args.push_back(poly(op.node));
            constant = constant && (args.back().empty() || (args.back().size() == 1 &&
                                                            args.back().begin()->first.empty()));
        }
        auto value = [](const Poly& p) { return p.empty() ? 0.0 : p.begin()->second; };
        // The graph writes powers that are not small integers as sqrt and pow.
        if (f == Function::sqrt) return power(args[0], 0.5);
        if (f == Function::pow) {
            if (args[1].empty() || (args[1].size() == 1 && args[1].begin()->first.empty()))
                return power(args[0], value(args[1]));
            return atom("\\left(" + print(args[0]) + "\\right)^{" + print(args[1]) + "}");
        }
        if (constant) {
            const double v =
                ir::evaluate(f, value(args[0]), args.size() > 1 ? value(args[1]) : 0.0);
            if (std::isfinite(v)) return v == 0 ? Poly{} : Poly{{Monomial{}, v}};
        }
        std::string inner;
        for (const Poly& a : args) inner += (inner.empty() ? "" : ", ") + print(a);
        if (f == Function::abs) return atom("\\left|" + inner + "\\right|");
        return atom(std::string(function_command(f)) + "\\left(" + inner + "\\right)");
    }
    }
    throw diag::InternalError("latex: unknown node kind");
}

Expander::Poly Expander::sum(const std::vector<std::pair<const Poly*, double>>& parts) const {
    // Contributions per monomial, summed in sorted order (independent of the
    // operand order); a sum that cancels to rounding is dropped.
    std::map<Monomial, std::vector<double>> contributions;
    for (const auto& [p, weight] : parts)
        for (const auto& [m, c] : *p) contributions[m].push_back(weight * c);
    Poly out;
    for (auto& [m, cs] : contributions) {
        std::sort(cs.begin(), cs.end());
        double s = 0, largest = 0;
        for (double c : cs) {
            s += c;
            largest = std::max(largest, std::fabs(c));
        }
        if (std::fabs(s) > 1e-12 * largest) out.emplace(m, s);
    }
    if (out.size() > max_terms_)
        throw TooLong("more than " + std::to_string(max_terms_) + " terms when expanded");
    return out;
}

Expander::Poly Expander::product(const Poly& a, const Poly& b) const {
    if (a.size() * b.size() > 50 * max_terms_)
        throw TooLong("more than " + std::to_string(max_terms_) + " terms when expanded");
    std::vector<Poly> pieces;
    pieces.reserve(a.size() * b.size());
    for (const auto& [ma, ca] : a)
        for (const auto& [mb, cb] : b) {
            Monomial m;
            std::size_t i = 0, j = 0;
            while (i < ma.size() || j < mb.size()) {
                if (j == mb.size() || (i < ma.size() && ma[i].first < mb[j].first)) {
                    m.push_back(ma[i++]);
                } else if (i == ma.size() || mb[j].first < ma[i].first) {
                    m.push_back(mb[j++]);
                } else {
                    const int e = ma[i].second + mb[j].second;
                    if (e != 0) m.emplace_back(ma[i].first, e);
                    ++i;
                    ++j;
                }
            }
            pieces.push_back(Poly{{std::move(m), ca * cb}});
        }
    std::vector<std::pair<const Poly*, double>> parts;
    for (const Poly& p : pieces) parts.push_back({&p, 1.0});
    return reduce_trigonometry(sum(parts));
}

// sin(x)^2 = 1 - cos(x)^2: with even powers of sines rewritten, sums such as
// J cos(psi)^2 + J sin(psi)^2 collapse to J, as a reader would write them.
Expander::Poly Expander::reduce_trigonometry(Poly p) const {
    static const std::string sine = "\\sin\\left(";
    for (;;) {
        auto term = p.end();
        std::size_t factor = 0;
        for (auto it = p.begin(); it != p.end() && term == p.end(); ++it)
            for (std::size_t i = 0; i < it->first.size(); ++i)
                if (it->first[i].second >= 2 &&
                    it->first[i].first.compare(0, sine.size(), sine) == 0) {
                    term = it;
                    factor = i;
                    break;
                }
        if (term == p.end()) return p;
        Monomial rest = term->first;
        const double c = term->second;
        const std::string cosine = "\\cos" + rest[factor].first.substr(4);
        if ((rest[factor].second -= 2) == 0) rest.erase(rest.begin() + static_cast<long>(factor));
        p.erase(term);
        const Poly one_minus_cos2{{Monomial{}, 1.0}, {Monomial{{cosine, 2}}, -1.0}};
        const Poly replaced = product(Poly{{rest, c}}, one_minus_cos2);
        p = sum({{&p, 1.0}, {&replaced, 1.0}});
    }
}

Expander::Poly Expander::power(const Poly& p, double exponent) const {
    if (exponent == 1) return p;
    if (p.empty()) {
        if (exponent > 0) return {};
        throw diag::InternalError("latex: a division by zero");
    }
    const bool monomial = p.size() == 1;
    if (is_integer(exponent) && exponent > 0) {
        Poly out{{Monomial{}, 1.0}};
        for (int k = 0; k < static_cast<int>(exponent); ++k) out = product(out, p);
        return out;
    }
    if (monomial && is_integer(exponent)) { // (c x^a)^-n = c^-n x^-an
        const auto& [m, c] = *p.begin();
        Monomial inverted;
        for (const auto& [a, e] : m) inverted.emplace_back(a, e * static_cast<int>(exponent));
        return Poly{{inverted, std::pow(c, exponent)}};
    }
    const std::string base = print(p);
    const bool simple = monomial && p.begin()->second == 1 && p.begin()->first.size() == 1 &&
                        p.begin()->first[0].second == 1;
    if (std::fabs(exponent) == 0.5) return atom("\\sqrt{" + base + "}", exponent > 0 ? 1 : -1);
    if (is_integer(exponent)) // a sum to a negative power
        return atom("\\left(" + base + "\\right)", static_cast<int>(exponent));
    return atom((simple ? base : "\\left(" + base + "\\right)") + "^{" + number(exponent) + "}");
}

std::vector<std::string> Expander::print_terms(const Poly& p) const {
    // Lower total degree first, then by the printed factors.
    std::vector<std::pair<std::pair<int, std::string>, std::string>> ordered;
    for (const auto& [m, c] : p) {
        int degree = 0;
        std::string numerator, denominator;
        // Factors by rank, then by text: symbols first, functions last.
        Monomial factors = m;
        auto rank = [&](const std::string& a) {
            auto it = rank_.find(a);
            if (it != rank_.end()) return it->second;
            return a.find("\\left") != std::string::npos || a.find("\\sqrt") != std::string::npos
                       ? 100
                       : 0;
        };
        std::stable_sort(factors.begin(), factors.end(), [&](const auto& x, const auto& y) {
            return rank(x.first) < rank(y.first);
        });
        for (const auto& [a, e] : factors) {
            degree += std::abs(e);
            const int n = std::abs(e);
            const std::string factor = a + (n == 1 ? "" : "^{" + std::to_string(n) + "}");
            std::string& side = e > 0 ? numerator : denominator;
            side += (side.empty() ? "" : " ") + factor;
        }
        std::string coefficient = number(std::fabs(c));
        if (coefficient == "1") coefficient.clear();
        std::string body;
        if (denominator.empty())
            body = coefficient.empty() ? (numerator.empty() ? "1" : numerator)
                                       : coefficient + (numerator.empty() ? "" : "\\," + numerator);
        else
            body = (coefficient.empty() ? "" : coefficient + "\\,") + "\\frac{" +
                   (numerator.empty() ? "1" : numerator) + "}{" + denominator + "}";
        std::string key;
        for (const auto& [a, e] : m) key += a + "^" + std::to_string(e) + " ";
        ordered.push_back({{degree, key}, (c < 0 ? "-" : "+") + body});
    }
    std::sort(ordered.begin(), ordered.end());
    std::vector<std::string> out;
    for (auto& o : ordered) out.push_back(std::move(o.second));
    return out;
}

std::string Expander::print(const Poly& p) const {
    const std::vector<std::string> t = print_terms(p);
    if (t.empty()) return "0";
    std::string out;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const bool negative = t[i][0] == '-';
        const std::string body = t[i].substr(1);
        if (i == 0)
            out += negative ? "-" + body : body;
        else
            out += (negative ? " - " : " + ") + body;
    }
    return out;
}

} // namespace yamsc::codegen::latex
