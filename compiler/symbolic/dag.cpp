#include "symbolic/dag.hpp"

#include "diag/diagnostics.hpp"

#include <cmath>
#include <unordered_set>

namespace yamsc::symbolic {

using namespace GiNaC;

namespace {

struct LambdaMap : map_function {
    const std::function<ex(const ex&)>& f;
    explicit LambdaMap(const std::function<ex(const ex&)>& fn) : f(fn) {}
    ex operator()(const ex& e) override { return f(e); }
};

std::string function_name(const ex& e) {
    return ex_to<function>(e).get_name();
}

} // namespace

// GiNaC's comparison of two equal expressions re-points one handle to the other's
// object (ex::share). Comparing a node of the DAG directly could therefore change a
// parent's operand while it is memoised by address; every comparison here goes
// through a copy of the handle instead (`ex(e)`).

ex map_operands(const ex& e, const std::function<ex(const ex&)>& f) {
    LambdaMap m(f);
    return e.map(m);
}

// ---- differentiation ---------------------------------------------------------------

ex Differentiator::operator()(const ex& e) {
    if (const ex* hit = memo_.find(e)) return *hit;
    ex r = compute(e);
    return memo_.put(e, r);
}

ex Differentiator::compute(const ex& e) {
    if (is_a<symbol>(e)) return ex(e).is_equal(s_) ? 1 : 0; // compare a copy: see above
    if (is_a<numeric>(e) || is_a<constant>(e)) return 0;
    if (is_a<add>(e)) {
        exvector terms;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            ex d = (*this)(e.op(i));
            if (!d.is_zero()) terms.push_back(d);
        }
        return terms.empty() ? ex(0) : ex(add(terms));
    }
    if (is_a<mul>(e)) {
        exvector terms;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            ex d = (*this)(e.op(i));
            if (d.is_zero()) continue;
            exvector factors;
            factors.reserve(e.nops());
            for (std::size_t j = 0; j < e.nops(); ++j) factors.push_back(j == i ? d : e.op(j));
            terms.push_back(mul(factors));
        }
        return terms.empty() ? ex(0) : ex(add(terms));
    }
    if (is_a<power>(e)) {
        const ex& b = e.op(0);
        const ex& x = e.op(1);
        ex db = (*this)(b);
        ex dx = (*this)(x);
        if (dx.is_zero()) {
            if (db.is_zero()) return 0;
            return x * pow(b, x - 1) * db;
        }
        return e * (dx * log(b) + x * db / b);
    }
    if (is_a<function>(e)) {
        const std::string name = function_name(e);
        if (name == "atan2") {
            const ex& y = e.op(0);
            const ex& x = e.op(1);
            ex dy = (*this)(y), dx = (*this)(x);
            if (dy.is_zero() && dx.is_zero()) return 0;
            return (x * dy - y * dx) / (x * x + y * y);
        }
        if (e.nops() != 1) throw diag::InternalError("cannot differentiate function " + name);
        const ex& a = e.op(0);
        ex da = (*this)(a);
        if (da.is_zero()) return 0;
        ex outer;
        if (name == "sin")
            outer = cos(a);
        else if (name == "cos")
            outer = -sin(a);
        else if (name == "tan")
            outer = 1 + pow(tan(a), 2);
        else if (name == "asin")
            outer = pow(1 - a * a, numeric(-1, 2));
        else if (name == "acos")
            outer = -pow(1 - a * a, numeric(-1, 2));
        else if (name == "atan")
            outer = pow(1 + a * a, -1);
        else if (name == "exp")
            outer = e;
        else if (name == "log")
            outer = pow(a, -1);
        else if (name == "abs")
            outer = a / e;
        else
            throw diag::InternalError("cannot differentiate function " + name);
        return outer * da;
    }
    throw diag::InternalError("cannot differentiate expression node of class " +
                              std::string(ex_to<basic>(e).class_name()));
}

// ---- substitution ---------------------------------------------------------------------

ex Substituter::operator()(const ex& e) {
    if (const ex* hit = memo_.find(e)) return *hit;
    ex r;
    if (is_a<symbol>(e)) {
        auto it = map_.find(ex(e));
        r = it == map_.end() ? e : it->second;
    } else if (e.nops() == 0) {
        r = e;
    } else {
        r = map_operands(e, [this](const ex& x) { return (*this)(x); });
    }
    return memo_.put(e, r);
}

// ---- dependence -------------------------------------------------------------------------

DependsOn::DependsOn(std::vector<symbol> symbols) : symbols_(std::move(symbols)) {}

bool DependsOn::operator()(const ex& e) {
    if (const bool* hit = memo_.find(e)) return *hit;
    bool r = false;
    if (is_a<symbol>(e)) {
        for (const auto& s : symbols_)
            if (ex(e).is_equal(s)) r = true;
    } else {
        for (std::size_t i = 0; i < e.nops() && !r; ++i) r = (*this)(e.op(i));
    }
    return memo_.put(e, r);
}

// ---- numeric evaluation -------------------------------------------------------------------

double Evaluator::operator()(const ex& e) {
    if (const double* hit = memo_.find(e)) return *hit;
    double r = 0;
    if (is_a<symbol>(e)) {
        auto it = values_.find(ex(e));
        if (it == values_.end())
            throw diag::InternalError("no value for symbol " + ex_to<symbol>(e).get_name());
        r = it->second;
    } else if (is_a<numeric>(e)) {
        r = ex_to<numeric>(e).to_double();
    } else if (is_a<constant>(e)) {
        r = ex_to<numeric>(e.evalf()).to_double();
    } else if (is_a<add>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i) r += (*this)(e.op(i));
    } else if (is_a<mul>(e)) {
        r = 1;
        for (std::size_t i = 0; i < e.nops(); ++i) r *= (*this)(e.op(i));
    } else if (is_a<power>(e)) {
        double b = (*this)(e.op(0));
        const ex& x = e.op(1);
        if (is_a<numeric>(x) && ex_to<numeric>(x).is_integer()) {
            long n = ex_to<numeric>(x).to_long();
            r = std::pow(b, static_cast<double>(n));
        } else {
            r = std::pow(b, (*this)(x));
        }
    } else if (is_a<function>(e)) {
        const std::string name = function_name(e);
        double a = (*this)(e.op(0));
        if (name == "sin")
            r = std::sin(a);
        else if (name == "cos")
            r = std::cos(a);
        else if (name == "tan")
            r = std::tan(a);
        else if (name == "asin")
            r = std::asin(a);
        else if (name == "acos")
            r = std::acos(a);
        else if (name == "atan")
            r = std::atan(a);
        else if (name == "exp")
            r = std::exp(a);
        else if (name == "log")
            r = std::log(a);
        else if (name == "abs")
            r = std::fabs(a);
        else if (name == "atan2")
            r = std::atan2(a, (*this)(e.op(1)));
        else
            throw diag::InternalError("cannot evaluate function " + name);
    } else {
        throw diag::InternalError("cannot evaluate expression node of class " +
                                  std::string(ex_to<basic>(e).class_name()));
    }
    return memo_.put(e, r);
}

std::size_t dag_size(const std::vector<ex>& roots) {
    // Every node visited stays alive: the operands of sums and products are made
    // on the fly (coefficient times term), and a freed one's address could come
    // back as another's and be taken for a node already seen.
    std::unordered_set<const basic*> seen;
    std::vector<ex> visited;
    std::vector<ex> stack(roots.begin(), roots.end());
    while (!stack.empty()) {
        ex e = stack.back();
        stack.pop_back();
        if (!seen.insert(node_id(e)).second) continue;
        visited.push_back(e);
        for (std::size_t i = 0; i < e.nops(); ++i) stack.push_back(e.op(i));
    }
    return seen.size();
}

} // namespace yamsc::symbolic
