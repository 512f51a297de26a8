#include "codegen/functions.hpp"

namespace yamsc::codegen {

std::vector<FunctionPlan> function_plans(const Module& module) {
    std::vector<FunctionPlan> plans;
    for (const Routine& r : module.routines) {
        if (r.internal) continue;
        FunctionPlan full;
        full.routine = &r;
        for (const Argument& a : r.arguments) full.parameters.push_back(&a);
        if (r.name == "mass_matrix" && module.mass_matrix_short_form) {
            FunctionPlan short_plan;
            short_plan.routine = &r;
            short_plan.short_form = true;
            for (const char* name : {"q", "p", "M"})
                short_plan.parameters.push_back(r.argument(name));
            plans.push_back(short_plan);
            full.forwards_to_short = true;
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
    return plans;
}

std::vector<std::string> parameter_names(const FunctionPlan& plan) {
    std::vector<std::string> names;
    for (const Argument* a : plan.parameters) names.push_back(a->name);
    return names;
}

} // namespace yamsc::codegen
