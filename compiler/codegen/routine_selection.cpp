// keep_routines: a module cut down to the routines one use calls. A model
// compiled on the fly for `yamsc sim` needs rhs and outputs only; the
// Jacobians and the linear model would be most of what the C++ compiler reads.
#include "codegen/module.hpp"
#include "diag/diagnostics.hpp"

#include <algorithm>
#include <set>

namespace yamsc::codegen {

namespace {

/// The routines a routine's steps call (sweeps and calls).
std::vector<std::string> callees(const Routine& r) {
    std::vector<std::string> out;
    for (const Step& s : r.steps) {
        if (s.kind == StepKind::sweep) out.push_back(s.sweep.callee);
        if (s.kind == StepKind::call) out.push_back(s.call.callee);
    }
    return out;
}

} // namespace

void keep_routines(Module& module, RoutineSet wanted) {
    std::set<std::string> keep;
    std::vector<std::string> pending;
    bool derivatives = false;
    wanted.for_each([&](RoutineId id) {
        const Routine& r = module.routine(id); // throws for a routine the module lacks
        derivatives = derivatives || routine_row(id).derivative;
        if (keep.insert(r.name).second) pending.push_back(r.name);
    });
    // The externals' wrappers (external_wrappers.hpp) call these.
    if (!module.externals.empty()) {
        keep.insert("external_args");
        if (derivatives) keep.insert("external_args_jacobian");
        if (wanted.contains(RoutineId::rhs_jacobian)) keep.insert("external_qdd_dw");
    }
    // Everything a kept routine calls is kept too, transitively.
    while (!pending.empty()) {
        const std::string name = pending.back();
        pending.pop_back();
        for (const std::string& callee : callees(module.routine(name)))
            if (keep.insert(callee).second) pending.push_back(callee);
    }
    auto dropped = [&](const Routine& r) { return keep.count(r.name) == 0; };
    module.routines.erase(std::remove_if(module.routines.begin(), module.routines.end(), dropped),
                          module.routines.end());
}

} // namespace yamsc::codegen
