#include "codegen/symbol_binding.hpp"

#include "diag/diagnostics.hpp"

#include <utility>

namespace yamsc::codegen {

Expr load(const std::string& array, int index) {
    Expr e;
    e.kind = ExprKind::load;
    e.array = array;
    e.index = index;
    return e;
}

Argument argument(const char* name, ArgumentKind kind) {
    return Argument{name, kind, false};
}

SymbolSource SymbolSource::state_vector(int nq) {
    SymbolSource s;
    s.q = "x";
    s.qd = "x";
    s.qd_offset = nq;
    return s;
}

SymbolSource SymbolSource::operating_point() {
    SymbolSource s;
    s.time.clear();
    s.q = "q0";
    s.qd = "qd0";
    s.u = "u0";
    s.a = "qdd0";
    return s;
}

RoutineBuilder::Binding bind(SymbolSource source) {
    return [s = std::move(source)](SymbolRef ref) -> std::optional<Expr> {
        auto from = [&](const std::string& array, int offset) -> std::optional<Expr> {
            if (array.empty()) return std::nullopt;
            return load(array, offset + ref.index);
        };
        switch (ref.kind) {
        case SymbolKind::time: {
            Expr e;
            e.kind = s.time.empty() ? ExprKind::number : ExprKind::time;
            return e;
        }
        case SymbolKind::q:
            return from(s.q, s.q_offset);
        case SymbolKind::qd:
            return from(s.qd, s.qd_offset);
        case SymbolKind::input:
            return from(s.u, 0);
        case SymbolKind::param: {
            Expr e;
            e.kind = ExprKind::param;
            e.index = ref.index;
            return e;
        }
        case SymbolKind::acceleration:
            return from(s.a, 0);
        case SymbolKind::qdd:
            return from(s.qdd, 0);
        case SymbolKind::seed:
            return from(s.seed, 0);
        }
        return std::nullopt;
    };
}

std::vector<Argument> point_arguments(std::vector<Argument> outputs) {
    std::vector<Argument> args{
        argument("q0", ArgumentKind::input_array), argument("qd0", ArgumentKind::input_array),
        argument("u0", ArgumentKind::input_array), argument("p", ArgumentKind::params)};
    for (Argument& a : outputs) args.push_back(std::move(a));
    return args;
}

namespace {

std::vector<Argument> q_form_arguments(std::vector<Argument> outputs) {
    std::vector<Argument> args{
        argument("t", ArgumentKind::scalar), argument("q", ArgumentKind::input_array),
        argument("qd", ArgumentKind::input_array), argument("u", ArgumentKind::input_array),
        argument("p", ArgumentKind::params)};
    for (Argument& a : outputs) args.push_back(std::move(a));
    return args;
}

std::vector<Argument> x_form_arguments(const char* output) {
    return {argument("t", ArgumentKind::scalar), argument("x", ArgumentKind::input_array),
            argument("u", ArgumentKind::input_array), argument("p", ArgumentKind::params),
            argument(output, ArgumentKind::output_array)};
}

Argument out(const char* name) {
    return argument(name, ArgumentKind::output_array);
}

} // namespace

RoutineBuilder::Signature api_signature(std::string_view name) {
    if (name == "mass_matrix")
        return {"mass_matrix",
                "M(q) of M q'' = F (symmetric, row-major)",
                {argument("t", ArgumentKind::scalar), argument("q", ArgumentKind::input_array),
                 argument("u", ArgumentKind::input_array), argument("p", ArgumentKind::params),
                 out("M")}};
    if (name == "forcing")
        return {"forcing", "F(q, q', u, t) of M q'' = F", q_form_arguments({out("F")})};
    if (name == "jacobians")
        return {"jacobians", "dF/dq, dF/dq', dF/du (nq x nq, nq x nq, nq x nu)",
                q_form_arguments({out("dF_dq"), out("dF_dqd"), out("dF_du")})};
    if (name == "outputs")
        return {"outputs", "the model's outputs y(q, q', u, t)", q_form_arguments({out("y")})};
    if (name == "outputs_from_qdd")
        return {"outputs_from_qdd",
                "the outputs y(q, q', q'', u, t) at the given q''; outputs passes the q'' of "
                "rhs",
                {argument("t", ArgumentKind::scalar), argument("q", ArgumentKind::input_array),
                 argument("qd", ArgumentKind::input_array),
                 argument("qdd", ArgumentKind::input_array),
                 argument("u", ArgumentKind::input_array), argument("p", ArgumentKind::params),
                 out("y")}};
    if (name == "rhs")
        return {"rhs", "x' = [q', M^-1 F] for x = [q, q']", x_form_arguments("xdot")};
    if (name == "rhs_jacobian")
        return {"rhs_jacobian", "d(rhs)/dx, 2nq x 2nq, row-major", x_form_arguments("J")};
    if (name == "linear")
        return {"linear",
                "M0 dq'' + C0 dq' + K0 dq = Q0 du about (q0, q0', u0), with q''0 = M0^-1 F0 "
                "(eq. 25)",
                point_arguments({out("M0"), out("C0"), out("K0"), out("Q0")})};
    if (name == "state_space")
        return {"state_space",
                "x' = A x + B u linearized about (q0, q0', u0); A 2nq x 2nq, B 2nq x nu",
                point_arguments({out("A"), out("B")})};
    if (name == "output_matrices")
        return {"output_matrices", "dy = C dx + D du about (q0, q0', u0); C ny x 2nq, D ny x nu",
                point_arguments({out("C"), out("D")})};
    throw diag::InternalError("code generation: no API function '" + std::string(name) + "'");
}

} // namespace yamsc::codegen
