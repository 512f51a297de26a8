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
        case SymbolKind::multiplier:
            return from(s.lambda, 0);
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

RoutineBuilder::Signature api_signature(RoutineId id) {
    const RoutineRow& row = routine_row(id);
    std::vector<Argument> args;
    auto inputs = [&](std::initializer_list<const char*> names) {
        for (const char* n : names)
            args.push_back(argument(n, n[0] == 't'   ? ArgumentKind::scalar
                                       : n[0] == 'p' ? ArgumentKind::params
                                                     : ArgumentKind::input_array));
    };
    switch (row.form) {
    case ArgumentForm::t_q_u_p:
        inputs({"t", "q", "u", "p"});
        break;
    case ArgumentForm::t_q_qd_u_p:
        inputs({"t", "q", "qd", "u", "p"});
        break;
    case ArgumentForm::t_q_qd_qdd_u_p:
        inputs({"t", "q", "qd", "qdd", "u", "p"});
        break;
    case ArgumentForm::t_x_u_p:
        inputs({"t", "x", "u", "p"});
        break;
    case ArgumentForm::point:
        args = point_arguments({});
        break;
    case ArgumentForm::p:
        inputs({"p"});
        break;
    case ArgumentForm::t_q_qd_u_lambda_a_p:
        inputs({"t", "q", "qd", "u", "lambda", "a", "p"});
        break;
    }
    for (const char* o : row.outputs)
        if (o) args.push_back(argument(o, ArgumentKind::output_array));
    return {row.name, row.summary, std::move(args), id};
}

} // namespace yamsc::codegen
