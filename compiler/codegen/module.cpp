#include "codegen/module.hpp"

#include "diag/diagnostics.hpp"

namespace yamsc::codegen {

bool is_leaf(const Expr& e) {
    return e.kind == ExprKind::number || e.kind == ExprKind::load || e.kind == ExprKind::param ||
           e.kind == ExprKind::time;
}

const Argument* Routine::argument(std::string_view name) const {
    for (const Argument& a : arguments)
        if (a.name == name) return &a;
    return nullptr;
}

const Routine& Module::routine(std::string_view name) const {
    for (const Routine& r : routines)
        if (r.name == name) return r;
    throw diag::InternalError("code generation: the module has no routine '" + std::string(name) +
                              "'");
}

const Routine& Module::routine(RoutineId id) const {
    for (const Routine& r : routines)
        if (r.id == id && !r.internal) return r;
    throw diag::InternalError("code generation: the module has no routine '" +
                              std::string(routine_name(id)) + "'");
}

} // namespace yamsc::codegen
