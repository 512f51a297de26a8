#include "model/flexible.hpp"

#include <cmath>

namespace yamsc::model {

namespace {

using Poly = std::vector<double>;
using K = Expr::Kind;
constexpr std::size_t max_degree = 32;

Poly constant(double v) {
    return Poly{v};
}

Poly add(const Poly& a, const Poly& b, double sign) {
    Poly r(std::max(a.size(), b.size()), 0.0);
    for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
    for (std::size_t i = 0; i < b.size(); ++i) r[i] += sign * b[i];
    return r;
}

Poly mul(const Poly& a, const Poly& b) {
    Poly r(a.size() + b.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
    return r;
}

bool is_constant(const Poly& p) {
    for (std::size_t i = 1; i < p.size(); ++i)
        if (p[i] != 0.0) return false;
    return true;
}

std::optional<Poly> poly(const Expr& e, const NameValues& values, std::string& why) {
    auto arg = [&](std::size_t i) { return poly(e.args[i], values, why); };
    switch (e.kind) {
    case K::name:
        if (e.text == "z" && e.primes == 0) return Poly{0.0, 1.0};
        break;
    case K::neg: {
        auto a = arg(0);
        if (!a) return a;
        return add(Poly{0.0}, *a, -1.0);
    }
    case K::add:
    case K::sub: {
        auto a = arg(0), b = arg(1);
        if (!a || !b) return std::nullopt;
        return add(*a, *b, e.kind == K::add ? 1.0 : -1.0);
    }
    case K::mul: {
        auto a = arg(0), b = arg(1);
        if (!a || !b) return std::nullopt;
        Poly r = mul(*a, *b);
        if (r.size() > max_degree + 1) {
            why = "has a degree above " + std::to_string(max_degree);
            return std::nullopt;
        }
        return r;
    }
    case K::div: {
        auto a = arg(0), b = arg(1);
        if (!a || !b) return std::nullopt;
        if (!is_constant(*b) || (*b)[0] == 0.0) {
            why = "divides by something that is not a non-zero constant";
            return std::nullopt;
        }
        for (double& c : *a) c /= (*b)[0];
        return a;
    }
    case K::pow: {
        auto a = arg(0), b = arg(1);
        if (!a || !b) return std::nullopt;
        double n = (*b)[0];
        if (!is_constant(*b) || n < 0 || n != std::floor(n) || n > double(max_degree)) {
            why = "raises to a power that is not a whole number from 0 to " +
                  std::to_string(max_degree);
            return std::nullopt;
        }
        Poly r = constant(1.0);
        for (int i = 0; i < static_cast<int>(n); ++i) r = mul(r, *a);
        if (r.size() > max_degree + 1) {
            why = "has a degree above " + std::to_string(max_degree);
            return std::nullopt;
        }
        return r;
    }
    default:
        break;
    }
    // Anything else must be a constant (numbers, parameters with defaults, functions).
    std::vector<const Expr*> names;
    collect_names(e, names);
    for (const Expr* n : names)
        if (n->text == "z") {
            why = "uses z inside a function";
            return std::nullopt;
        }
    auto v = evaluate_with(e, values, why);
    if (!v) return std::nullopt;
    return constant(*v);
}

} // namespace

std::optional<std::vector<double>> polynomial_in_z(const Expr& e, const NameValues& values,
                                                   std::string& why) {
    return poly(e, values, why);
}

} // namespace yamsc::model
