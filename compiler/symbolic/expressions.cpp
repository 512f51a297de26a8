#include "symbolic/expressions.hpp"

#include "diag/diagnostics.hpp"
#include "model/names.hpp"

#include <cctype>

namespace yamsc::symbolic {

using namespace GiNaC;
using K = model::Expr::Kind;

namespace {

const char* prime_suffix(int primes) {
    return primes == 0 ? "" : primes == 1 ? "_d" : "_dd";
}

} // namespace

Symbols::Symbols(const model::Model& m) : t_("t") {
    for (const auto& d : m.dofs) {
        Dof dof{d.name, d.doc, symbol(d.name), symbol(d.name + "_d"), symbol(d.name + "_dd")};
        by_name_[0][d.name] = dof.q;
        by_name_[1][d.name] = dof.qd;
        by_name_[2][d.name] = dof.qdd;
        dofs_.push_back(dof);
    }
    for (const auto& in : m.inputs) {
        for (int k = 0; k <= in.order; ++k) {
            InputChannel c;
            c.name = in.name + std::string(static_cast<std::size_t>(k), '\'');
            c.c_name = in.name + prime_suffix(k);
            c.doc = k == 0 ? in.doc : "derivative " + std::to_string(k) + " of " + in.name;
            c.sym = symbol(c.c_name);
            by_name_[k][in.name] = c.sym;
            next_channel_.push_back(k < in.order ? static_cast<int>(channels_.size()) + 1 : -1);
            channels_.push_back(c);
        }
    }
    for (const auto& p : m.params) {
        Parameter par{p.name, p.doc, p.value, symbol(p.name)};
        by_name_[0][p.name] = par.sym;
        params_.push_back(par);
    }
}

ex Symbols::lookup(const std::string& name, int primes) const {
    if (name == "t" && primes == 0) return t_;
    if (name == "pi" && primes == 0) return Pi;
    if (primes < 0 || primes > 2) throw diag::InternalError("bad derivative order of " + name);
    auto it = by_name_[primes].find(name);
    if (it == by_name_[primes].end())
        throw diag::InternalError("unresolved name " + name + " after checking");
    return it->second;
}

ex Symbols::diff(const ex& e, const symbol& s) {
    auto& d = diffs_[s.get_name()];
    if (!d) d = std::make_unique<Differentiator>(s);
    return (*d)(e);
}

ex Symbols::time_derivative(const ex& e, bool with_qdd) {
    exvector terms;
    for (const auto& d : dofs_) {
        ex a = diff(e, d.q);
        if (!a.is_zero()) terms.push_back(a * d.qd);
        ex b = diff(e, d.qd);
        if (!b.is_zero() && with_qdd) terms.push_back(b * d.qdd);
    }
    explicit_time_terms(e, terms);
    return terms.empty() ? ex(0) : ex(add(terms));
}

ex Symbols::explicit_time_derivative(const ex& e) {
    exvector terms;
    explicit_time_terms(e, terms);
    return terms.empty() ? ex(0) : ex(add(terms));
}

void Symbols::explicit_time_terms(const ex& e, exvector& terms) {
    for (std::size_t i = 0; i < channels_.size(); ++i) {
        ex a = diff(e, channels_[i].sym);
        if (a.is_zero()) continue;
        if (next_channel_[i] < 0)
            throw diag::InternalError("derivative of input channel " + channels_[i].name +
                                      " beyond its order");
        terms.push_back(a * channels_[static_cast<std::size_t>(next_channel_[i])].sym);
    }
    ex a = diff(e, t_);
    if (!a.is_zero()) terms.push_back(a);
}

ex exact_number(const std::string& text) {
    std::string digits;
    long exponent = 0;
    std::size_t i = 0;
    bool negative = false;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) negative = text[i++] == '-';
    bool seen_point = false;
    for (; i < text.size(); ++i) {
        char c = text[i];
        if (std::isdigit(static_cast<unsigned char>(c))) {
            digits += c;
            if (seen_point) --exponent;
        } else if (c == '.' && !seen_point) {
            seen_point = true;
        } else {
            break;
        }
    }
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        // The checker has already verified the literal is a finite double: the exponent is small.
        exponent += std::stol(text.substr(i + 1));
    }
    if (digits.empty()) throw diag::InternalError("bad number literal " + text);
    numeric mantissa(digits.c_str());
    ex value = mantissa * pow(numeric(10), numeric(exponent));
    return negative ? -value : value;
}

namespace {

ex call(const std::string& f, const exvector& a) {
    if (f == "sin") return sin(a[0]);
    if (f == "cos") return cos(a[0]);
    if (f == "tan") return tan(a[0]);
    if (f == "asin") return asin(a[0]);
    if (f == "acos") return acos(a[0]);
    if (f == "atan") return atan(a[0]);
    if (f == "atan2") return atan2(a[0], a[1]);
    if (f == "sqrt") return sqrt(a[0]);
    if (f == "exp") return exp(a[0]);
    if (f == "log") return log(a[0]);
    if (f == "abs") return abs(a[0]);
    throw diag::InternalError("unknown function " + f + " after checking");
}

struct Converter {
    const Symbols& symbols;
    const KinematicsHook& kin;

    Vec3 vec(const model::Expr& e) {
        switch (e.kind) {
        case K::vector:
            return {{scalar(e.args[0]), scalar(e.args[1]), scalar(e.args[2])}};
        case K::call: {
            if (!kin) throw diag::InternalError("kinematic function outside outputs");
            return kin(e.text, e.args[0]);
        }
        case K::neg:
            return -vec(e.args[0]);
        case K::add:
            return vec(e.args[0]) + vec(e.args[1]);
        case K::sub:
            return vec(e.args[0]) - vec(e.args[1]);
        case K::mul:
            if (is_vector(e.args[0])) return scalar(e.args[1]) * vec(e.args[0]);
            return scalar(e.args[0]) * vec(e.args[1]);
        case K::div:
            return pow(scalar(e.args[1]), -1) * vec(e.args[0]);
        case K::deg:
            return (Pi / 180) * vec(e.args[0]);
        default:
            throw diag::InternalError("not a vector expression: " + ast::to_string(e));
        }
    }

    static bool is_vector(const model::Expr& e) {
        switch (e.kind) {
        case K::vector:
            return true;
        case K::call:
            return model::is_kinematic_function(e.text);
        case K::neg:
        case K::deg:
            return is_vector(e.args[0]);
        case K::add:
        case K::sub:
        case K::div:
            return is_vector(e.args[0]);
        case K::mul:
            return is_vector(e.args[0]) || is_vector(e.args[1]);
        default:
            return false;
        }
    }

    ex scalar(const model::Expr& e) {
        switch (e.kind) {
        case K::number:
            return exact_number(e.text);
        case K::name:
            return symbols.lookup(e.text, e.primes);
        case K::neg:
            return -scalar(e.args[0]);
        case K::add:
            return scalar(e.args[0]) + scalar(e.args[1]);
        case K::sub:
            return scalar(e.args[0]) - scalar(e.args[1]);
        case K::mul:
            return scalar(e.args[0]) * scalar(e.args[1]);
        case K::div:
            return scalar(e.args[0]) * pow(scalar(e.args[1]), -1);
        case K::pow:
            return pow(scalar(e.args[0]), scalar(e.args[1]));
        case K::deg:
            return scalar(e.args[0]) * Pi / 180;
        case K::call: {
            exvector a;
            for (const auto& x : e.args) a.push_back(scalar(x));
            return call(e.text, a);
        }
        case K::component: {
            Vec3 v = vec(e.args[0]);
            std::size_t i = e.text == "x" ? 0 : e.text == "y" ? 1 : 2;
            return v[i];
        }
        case K::vector:
        case K::section:
            throw diag::InternalError("vector where a scalar was checked");
        }
        throw diag::InternalError("unknown expression kind");
    }
};

} // namespace

ex to_ginac(const model::Expr& e, const Symbols& symbols, const KinematicsHook& kin) {
    Converter c{symbols, kin};
    return c.scalar(e);
}

Vec3 to_ginac_vec(const model::Expr& e, const Symbols& symbols, const KinematicsHook& kin) {
    Converter c{symbols, kin};
    return c.vec(e);
}

Vec3 to_ginac(const model::Vec& v, const Symbols& symbols) {
    return {{to_ginac(v[0], symbols), to_ginac(v[1], symbols), to_ginac(v[2], symbols)}};
}

} // namespace yamsc::symbolic
