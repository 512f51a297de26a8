#include "analysis/trim_point.hpp"

#include "diag/diagnostics.hpp"
#include "driver/bindings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace yamsc::driver {

runtime::TrimResult trim_point(const runtime::ModelView& view, const std::vector<double>& q,
                               const std::vector<double>& qd, const std::vector<double>& u,
                               const std::vector<std::string>& hold) {
    std::vector<bool> held(q.size(), false);
    for (std::size_t i = 0; i < qd.size(); ++i) held[i] = qd[i] != 0.0;
    for (const std::string& name : hold) {
        const auto at = std::find(view.dof_names.begin(), view.dof_names.end(), name);
        if (at == view.dof_names.end())
            throw UserError("--hold: unknown DOF '" + name + "'" +
                            diag::did_you_mean(name, view.dof_names));
        held[static_cast<std::size_t>(at - view.dof_names.begin())] = true;
    }
    runtime::TrimResult r = runtime::trim(view, q, qd, u, held);
    if (r.converged) return r;
    std::string message = "trim did not converge after " + std::to_string(r.iterations) +
                          " Newton steps: max |F| over the free DOFs is " +
                          std::to_string(r.max_free_residual) + " (tolerance " +
                          std::to_string(r.tolerance) + "); residual by DOF:";
    for (std::size_t i = 0; i < r.q.size(); ++i) {
        char line[160];
        std::snprintf(line, sizeof line, "\n  %-16s q = %-14.8g F = %-12.4g%s",
                      view.dof_names[i].c_str(), r.q[i], r.residual[i], r.held[i] ? " (held)" : "");
        message += line;
    }
    message += "\nA free DOF with a constant load and no stiffness has no equilibrium: hold it "
               "(--hold) or give it a rate.";
    throw UserError(message);
}

} // namespace yamsc::driver
