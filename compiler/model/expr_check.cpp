#include "model/expr_check.hpp"

#include <cmath>
#include <cstdlib>

namespace yamsc::model {

using K = Expr::Kind;
using diag::Kind;

namespace {

std::vector<std::string> names_of(const SymbolTable& names) {
    std::vector<std::string> out;
    for (const auto& [name, info] : names) out.push_back(name);
    return out;
}

const char* kind_word(NameKind k) {
    switch (k) {
    case NameKind::param:
        return "parameter";
    case NameKind::input:
        return "input";
    case NameKind::dof:
        return "DOF";
    case NameKind::body:
        return "body";
    case NameKind::point:
        return "point";
    case NameKind::time:
        return "time";
    }
    return "name";
}

std::string primes(int n) {
    return std::string(static_cast<std::size_t>(n), '\'');
}

} // namespace

Shape ExprChecker::check_name(const Expr& e, const ExprContext& ctx) {
    if (e.text == "pi" && e.primes == 0) return Shape::scalar;
    if (e.text == "t") {
        if (!ctx.time) {
            diags_.error(Kind::WrongKind, e.loc, "time 't' cannot appear in " + ctx.what);
            return Shape::invalid;
        }
        if (e.primes > 0) {
            diags_.error(Kind::Derivative, e.loc, "time 't' has no time derivative");
            return Shape::invalid;
        }
        return Shape::scalar;
    }
    auto it = names_.find(e.text);
    if (it == names_.end()) {
        diags_.error(Kind::UnknownName, e.loc,
                     "unknown name '" + e.text + "'" +
                         diag::did_you_mean(e.text, names_of(names_)));
        return Shape::invalid;
    }
    const NameInfo& info = it->second;
    switch (info.kind) {
    case NameKind::param:
        if (e.primes > 0) {
            diags_.error(Kind::Derivative, e.loc,
                         "parameter '" + e.text + "' is constant: '" + e.text + primes(e.primes) +
                             "' is not allowed");
            return Shape::invalid;
        }
        return Shape::scalar;
    case NameKind::dof:
        if (!ctx.dofs) {
            diags_.error(Kind::WrongKind, e.loc,
                         "DOF '" + e.text + "' cannot appear in " + ctx.what +
                             " (only parameters and numbers may)");
            return Shape::invalid;
        }
        if (e.primes > ctx.dof_primes) {
            diags_.error(Kind::Derivative, e.loc,
                         "'" + e.text + primes(e.primes) + "' is not allowed in " + ctx.what +
                             (ctx.dof_primes == 0
                                  ? " (no time derivatives here)"
                                  : " (at most " + std::to_string(ctx.dof_primes) + " primes)"));
            return Shape::invalid;
        }
        return Shape::scalar;
    case NameKind::input: {
        if (!ctx.inputs) {
            diags_.error(Kind::WrongKind, e.loc,
                         "input '" + e.text + "' cannot appear in " + ctx.what +
                             " (only parameters and numbers may)");
            return Shape::invalid;
        }
        const Input& in = inputs_[static_cast<std::size_t>(info.index)];
        int needed = e.primes + ctx.input_extra_order;
        if (needed > in.order) {
            std::string msg = "'" + e.text + primes(e.primes) +
                              "' needs the derivatives of input '" + e.text + "' up to order " +
                              std::to_string(needed) + ": declare it `input " + e.text + " order " +
                              std::to_string(needed) + "`";
            if (ctx.input_extra_order > 0)
                msg += " (a prescribed motion needs the velocity and acceleration)";
            diags_.error(Kind::Derivative, e.loc, msg);
            return Shape::invalid;
        }
        return Shape::scalar;
    }
    case NameKind::body:
    case NameKind::point:
    case NameKind::time:
        diags_.error(Kind::WrongKind, e.loc,
                     std::string(kind_word(info.kind)) + " '" + e.text +
                         "' is not a value here; use position(" + e.text + ") or velocity(" +
                         e.text + ") in an output");
        return Shape::invalid;
    }
    return Shape::invalid;
}

Shape ExprChecker::check_call(const Expr& e, const ExprContext& ctx) {
    if (is_kinematic_function(e.text)) {
        if (!ctx.kinematics) {
            diags_.error(Kind::WrongKind, e.loc,
                         e.text + "() can only be used in an output, not in " + ctx.what);
            return Shape::invalid;
        }
        if (e.args.size() == 1 && e.args[0].kind == K::section) {
            if (!is_reaction_function(e.text)) {
                diags_.error(Kind::WrongKind, e.args[0].loc,
                             e.text + "() takes a body or point; a section (`" +
                                 ast::to_string(e.args[0]) +
                                 "`) is an argument of reaction_force() and reaction_moment()");
                return Shape::invalid;
            }
            return check_section(e.args[0]) ? Shape::vector : Shape::invalid;
        }
        if (e.args.size() != 1 || e.args[0].kind != K::name || e.args[0].primes != 0) {
            diags_.error(Kind::InvalidValue, e.loc,
                         e.text + "() takes the name of one body or point");
            return Shape::invalid;
        }
        if (is_reaction_function(e.text) && !ctx.reactions) {
            diags_.error(Kind::WrongKind, e.loc, e.text + "() cannot be used in " + ctx.what);
            return Shape::invalid;
        }
        const Expr& target = e.args[0];
        if (target.text == "ground") {
            if (!is_reaction_function(e.text)) return Shape::vector;
            diags_.error(Kind::WrongKind, target.loc,
                         e.text + "() takes a body; ground has no joint");
            return Shape::invalid;
        }
        auto it = names_.find(target.text);
        if (it == names_.end()) {
            std::vector<std::string> candidates;
            for (const auto& [name, info] : names_)
                if (info.kind == NameKind::body || info.kind == NameKind::point)
                    candidates.push_back(name);
            diags_.error(Kind::UnknownName, target.loc,
                         "unknown body or point '" + target.text + "'" +
                             diag::did_you_mean(target.text, candidates));
            return Shape::invalid;
        }
        if (it->second.kind != NameKind::body && it->second.kind != NameKind::point) {
            diags_.error(Kind::WrongKind, target.loc,
                         e.text + "() takes a body or point, but '" + target.text + "' is a " +
                             kind_word(it->second.kind));
            return Shape::invalid;
        }
        if ((e.text == "angular_velocity" || is_reaction_function(e.text)) &&
            it->second.kind == NameKind::point) {
            diags_.error(Kind::WrongKind, target.loc,
                         e.text + "() takes a body; '" + target.text + "' is a point" +
                             (is_reaction_function(e.text)
                                  ? " (a section of a flexible body is written `tower.node(10)` "
                                    "or `tower.tip`)"
                                  : ""));
            return Shape::invalid;
        }
        return Shape::vector;
    }
    int arity = function_arity(e.text);
    if (arity < 0) {
        std::vector<std::string> known = {"sin",
                                          "cos",
                                          "tan",
                                          "asin",
                                          "acos",
                                          "atan",
                                          "atan2",
                                          "sqrt",
                                          "exp",
                                          "log",
                                          "abs",
                                          "position",
                                          "velocity",
                                          "angular_velocity",
                                          "reaction_force",
                                          "reaction_moment"};
        diags_.error(Kind::UnknownName, e.loc,
                     "unknown function '" + e.text + "'" + diag::did_you_mean(e.text, known));
        return Shape::invalid;
    }
    if (static_cast<int>(e.args.size()) != arity) {
        diags_.error(Kind::InvalidValue, e.loc,
                     e.text + "() takes " + std::to_string(arity) + " argument" +
                         (arity == 1 ? "" : "s") + ", not " + std::to_string(e.args.size()));
        return Shape::invalid;
    }
    bool ok = true;
    for (const Expr& a : e.args) ok = scalar(a, ctx) && ok;
    return ok ? Shape::scalar : Shape::invalid;
}

bool ExprChecker::check_section(const Expr& e) {
    const Expr& body = e.args[0];
    auto it = body.kind == K::name && body.primes == 0 ? names_.find(body.text) : names_.end();
    if (it == names_.end() || it->second.kind != NameKind::body) {
        diags_.error(
            body.kind == K::name && it == names_.end() ? Kind::UnknownName : Kind::WrongKind,
            body.loc, "a section `." + e.text + "` needs the name of a flexible body before it");
        return false;
    }
    if (e.args.size() > 1) {
        std::string why;
        if (!evaluate_constant(e.args[1], why)) {
            diags_.error(Kind::NotConstant, e.args[1].loc, "the node number " + why);
            return false;
        }
    }
    return true; // the checker resolves the node (checker.cpp)
}

Shape ExprChecker::check(const Expr& e, const ExprContext& ctx) {
    switch (e.kind) {
    case K::number: {
        std::string why;
        if (!evaluate_constant(e, why)) {
            diags_.error(Kind::InvalidValue, e.loc, "number '" + e.text + "' " + why);
            return Shape::invalid;
        }
        return Shape::scalar;
    }
    case K::name:
        return check_name(e, ctx);
    case K::call:
        return check_call(e, ctx);
    case K::neg:
    case K::deg: {
        Shape s = check(e.args[0], ctx);
        return s;
    }
    case K::add:
    case K::sub: {
        Shape a = check(e.args[0], ctx), b = check(e.args[1], ctx);
        if (a == Shape::invalid || b == Shape::invalid) return Shape::invalid;
        if (a != b) {
            diags_.error(Kind::InvalidValue, e.loc, "cannot add a vector and a scalar");
            return Shape::invalid;
        }
        return a;
    }
    case K::mul: {
        Shape a = check(e.args[0], ctx), b = check(e.args[1], ctx);
        if (a == Shape::invalid || b == Shape::invalid) return Shape::invalid;
        if (a == Shape::vector && b == Shape::vector) {
            diags_.error(Kind::InvalidValue, e.loc,
                         "cannot multiply two vectors (write the components out)");
            return Shape::invalid;
        }
        return (a == Shape::vector || b == Shape::vector) ? Shape::vector : Shape::scalar;
    }
    case K::div: {
        Shape a = check(e.args[0], ctx), b = check(e.args[1], ctx);
        if (a == Shape::invalid || b == Shape::invalid) return Shape::invalid;
        if (b == Shape::vector) {
            diags_.error(Kind::InvalidValue, e.loc, "cannot divide by a vector");
            return Shape::invalid;
        }
        return a;
    }
    case K::pow: {
        bool ok = scalar(e.args[0], ctx);
        ok = scalar(e.args[1], ctx) && ok;
        return ok ? Shape::scalar : Shape::invalid;
    }
    case K::vector: {
        if (e.args.size() != 3) {
            diags_.error(Kind::InvalidValue, e.loc,
                         "a vector has 3 components, this one has " +
                             std::to_string(e.args.size()));
            return Shape::invalid;
        }
        bool ok = true;
        for (const Expr& a : e.args) ok = scalar(a, ctx) && ok;
        return ok ? Shape::vector : Shape::invalid;
    }
    case K::section:
        diags_.error(Kind::WrongKind, e.loc,
                     "a section (`" + ast::to_string(e) +
                         "`) is only an argument of reaction_force() and reaction_moment()");
        return Shape::invalid;
    case K::component: {
        Shape s = check(e.args[0], ctx);
        if (s == Shape::invalid) return s;
        if (s != Shape::vector) {
            diags_.error(Kind::InvalidValue, e.loc, "." + e.text + " applies to a vector");
            return Shape::invalid;
        }
        if (e.text != "x" && e.text != "y" && e.text != "z") {
            diags_.error(Kind::InvalidValue, e.loc,
                         "unknown component '." + e.text + "' (a vector has .x, .y and .z)");
            return Shape::invalid;
        }
        return Shape::scalar;
    }
    }
    return Shape::invalid;
}

bool ExprChecker::scalar(const Expr& e, const ExprContext& ctx) {
    Shape s = check(e, ctx);
    if (s == Shape::vector) {
        diags_.error(Kind::InvalidValue, e.loc,
                     "expected a scalar in " + ctx.what + ", not a vector");
        return false;
    }
    return s == Shape::scalar;
}

std::optional<Vec> ExprChecker::vector(const Expr& e, const ExprContext& ctx) {
    if (e.kind != K::vector || e.args.size() != 3) {
        if (e.kind == K::vector) {
            check(e, ctx);
        } else {
            diags_.error(Kind::InvalidValue, e.loc, "expected a vector (x, y, z) for " + ctx.what);
        }
        return std::nullopt;
    }
    bool ok = true;
    for (const Expr& a : e.args) ok = scalar(a, ctx) && ok;
    if (!ok) return std::nullopt;
    return Vec{e.args[0], e.args[1], e.args[2]};
}

namespace {

std::optional<double> eval(const Expr& e, std::string& why, const NameValues* names) {
    auto arg = [&](std::size_t i) { return eval(e.args[i], why, names); };
    switch (e.kind) {
    case K::number: {
        char* end = nullptr;
        double v = std::strtod(e.text.c_str(), &end);
        if (end == e.text.c_str() || *end != '\0') {
            why = "is not a valid number";
            return std::nullopt;
        }
        if (!std::isfinite(v) || (v != 0.0 && std::fabs(v) < 1e-300)) {
            why = "is out of the range of double precision";
            return std::nullopt;
        }
        return v;
    }
    case K::name:
        if (e.text == "pi" && e.primes == 0) return M_PI;
        if (names && e.primes == 0) {
            auto it = names->find(e.text);
            if (it != names->end()) return it->second;
        }
        why = "uses '" + e.text + "'";
        return std::nullopt;
    case K::neg: {
        auto a = arg(0);
        if (!a) return a;
        return -*a;
    }
    case K::deg: {
        auto a = arg(0);
        if (!a) return a;
        return *a * M_PI / 180.0;
    }
    case K::add:
    case K::sub:
    case K::mul:
    case K::div:
    case K::pow: {
        auto a = arg(0);
        if (!a) return a;
        auto b = arg(1);
        if (!b) return b;
        double r = e.kind == K::add   ? *a + *b
                   : e.kind == K::sub ? *a - *b
                   : e.kind == K::mul ? *a * *b
                   : e.kind == K::div ? *a / *b
                                      : std::pow(*a, *b);
        if (!std::isfinite(r)) {
            why = "is not finite";
            return std::nullopt;
        }
        return r;
    }
    case K::call: {
        std::vector<double> v;
        for (std::size_t i = 0; i < e.args.size(); ++i) {
            auto a = arg(i);
            if (!a) return a;
            v.push_back(*a);
        }
        double r = NAN;
        const std::string& f = e.text;
        if (v.size() == 1) {
            double x = v[0];
            r = f == "sin"    ? std::sin(x)
                : f == "cos"  ? std::cos(x)
                : f == "tan"  ? std::tan(x)
                : f == "asin" ? std::asin(x)
                : f == "acos" ? std::acos(x)
                : f == "atan" ? std::atan(x)
                : f == "sqrt" ? std::sqrt(x)
                : f == "exp"  ? std::exp(x)
                : f == "log"  ? std::log(x)
                : f == "abs"  ? std::fabs(x)
                              : NAN;
        } else if (v.size() == 2 && f == "atan2") {
            r = std::atan2(v[0], v[1]);
        }
        if (!std::isfinite(r)) {
            why = "is not finite (" + f + " out of its domain?)";
            return std::nullopt;
        }
        return r;
    }
    case K::vector:
    case K::component:
    case K::section:
        why = "is not a scalar";
        return std::nullopt;
    }
    return std::nullopt;
}

} // namespace

std::optional<double> evaluate_constant(const Expr& e, std::string& why) {
    return eval(e, why, nullptr);
}

std::optional<double> evaluate_with(const Expr& e, const NameValues& names, std::string& why) {
    return eval(e, why, &names);
}

void collect_names(const Expr& e, std::vector<const Expr*>& out) {
    if (e.kind == K::name) out.push_back(&e);
    for (const Expr& a : e.args) collect_names(a, out);
}

} // namespace yamsc::model
