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

void keep_routines(Module& module, const std::vector<std::string>& wanted) {
    std::set<std::string> keep;
    std::vector<std::string> pending;
    for (const std::string& name : wanted) {
        const Routine& r = module.routine(name); // throws for an unknown name
        if (r.internal) throw diag::InternalError("code generation: '" + name + "' is internal");
        if (keep.insert(name).second) pending.push_back(name);
    }
    // The externals' wrappers (external_wrappers.hpp) call these.
    if (!module.externals.empty()) {
        keep.insert("external_args");
        for (const char* r :
             {"jacobians", "rhs_jacobian", "linear", "state_space", "output_matrices"})
            if (keep.count(r)) keep.insert("external_args_jacobian");
        if (keep.count("rhs_jacobian")) keep.insert("external_qdd_dw");
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
