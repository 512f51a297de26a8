#include "codegen/functions.hpp"

#include "diag/diagnostics.hpp"

#include <algorithm>

namespace yamsc::codegen {

std::vector<FunctionPlan> function_plans(const Module& module) {
    std::vector<FunctionPlan> plans;
    for (const Routine& r : module.routines) {
        if (r.internal) continue;
        FunctionPlan full;
        full.routine = &r;
        for (const Argument& a : r.arguments) full.parameters.push_back(&a);
        if (r.id == RoutineId::mass_matrix && module.mass_matrix_short_form) {
            FunctionPlan short_plan;
            short_plan.routine = &r;
            short_plan.short_form = true;
            for (const char* name : {"q", "p", "M"})
                short_plan.parameters.push_back(r.argument(name));
            plans.push_back(short_plan);
            full.forwards_to_short = true;
            for (const Argument* a : full.parameters)
                if (std::find(short_plan.parameters.begin(), short_plan.parameters.end(), a) ==
                    short_plan.parameters.end())
                    full.not_forwarded.push_back(a);
        }
        plans.push_back(full);
    }
    return plans;
}

std::vector<FunctionPlan> internal_function_plans(const Module& module) {
    std::vector<FunctionPlan> plans;
    for (const Routine& r : module.routines) {
        if (!r.internal) continue;
        FunctionPlan plan;
        plan.routine = &r;
        for (const Argument& a : r.arguments) plan.parameters.push_back(&a);
        plans.push_back(plan);
    }
    // Defined in the generated file without declarations: callees first.
    std::vector<FunctionPlan> ordered;
    for (std::size_t i : callees_first(plans)) ordered.push_back(plans[i]);
    return ordered;
}

std::vector<std::size_t> callees_first(const std::vector<FunctionPlan>& plans) {
    auto calls = [](const Routine& caller, const std::string& callee) {
        for (const Step& s : caller.steps)
            if ((s.kind == StepKind::call && s.call.callee == callee) ||
                (s.kind == StepKind::sweep && s.sweep.callee == callee))
                return true;
        return false;
    };
    std::vector<std::size_t> order;
    std::vector<bool> placed(plans.size(), false);
    // Repeatedly the first plan whose callees among the plans are all placed:
    // quadratic in the handful of routines a module has.
    while (order.size() < plans.size()) {
        bool progress = false;
        for (std::size_t i = 0; i < plans.size(); ++i) {
            if (placed[i]) continue;
            bool ready = true;
            for (std::size_t j = 0; j < plans.size() && ready; ++j)
                if (!placed[j] && j != i && calls(*plans[i].routine, plans[j].routine->name))
                    ready = false;
            if (!ready) continue;
            placed[i] = true;
            order.push_back(i);
            progress = true;
            break;
        }
        if (!progress)
            throw diag::InternalError("code generation: the routines call each other in a cycle");
    }
    return order;
}

std::vector<std::string> parameter_names(const FunctionPlan& plan) {
    std::vector<std::string> names;
    for (const Argument* a : plan.parameters) names.push_back(a->name);
    return names;
}

} // namespace yamsc::codegen
