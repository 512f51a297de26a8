#include "analysis/trim_point.hpp"

#include "diag/diagnostics.hpp"
#include "driver/bindings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace yamsc::analysis {

using diag::UserError;

namespace {

std::size_t index_of(const std::string& name, const std::vector<std::string>& names,
                     const char* option, const char* what) {
    const auto at = std::find(names.begin(), names.end(), name);
    if (at == names.end())
        throw UserError(std::string(option) + ": unknown " + what + " '" + name + "'" +
                        diag::did_you_mean(name, names));
    return static_cast<std::size_t>(at - names.begin());
}

} // namespace

runtime::TrimResult trim_point(const runtime::ModelView& view, const std::vector<double>& q,
                               const std::vector<double>& qd, const std::vector<double>& u,
                               const std::vector<std::string>& hold,
                               const std::vector<std::string>& adjust,
                               const runtime::TrimSettings& settings) {
    std::vector<bool> held(q.size(), false);
    runtime::TrimAdjustment adjustment;
    for (std::size_t i = 0; i < qd.size(); ++i) {
        held[i] = qd[i] != 0.0;
        if (held[i] && !adjust.empty()) adjustment.balanced.push_back(static_cast<int>(i));
    }
    for (const std::string& name : hold)
        held[index_of(name, view.dof_names, "--hold", "DOF")] = true;
    for (const std::string& name : adjust)
        adjustment.inputs.push_back(
            static_cast<int>(index_of(name, view.input_names, "--adjust", "input")));
    if (adjustment.inputs.size() != adjustment.balanced.size()) {
        std::string spinning;
        for (int i : adjustment.balanced)
            spinning +=
                (spinning.empty() ? "" : ", ") + view.dof_names[static_cast<std::size_t>(i)];
        throw UserError("--adjust: " + std::to_string(adjustment.inputs.size()) + " input(s) for " +
                        std::to_string(adjustment.balanced.size()) + " DOF(s) held at a rate (" +
                        (spinning.empty() ? "none" : spinning) +
                        "): each adjusted input balances one of them (a DOF is held at the rate "
                        "--at gives it, e.g. --at \"psi'=1.2671\")");
    }
    runtime::TrimResult r = runtime::trim(view, q, qd, u, held, 0.0, settings, adjustment);
    if (r.converged) return r;
    const std::string passes = r.discrete_passes > 0
                                   ? " and " + std::to_string(r.discrete_passes) +
                                         " passes settling the blocks' discrete states"
                                   : "";
    std::string message = "trim did not converge after " + std::to_string(r.iterations) +
                          " Newton steps" + passes + ": max |F| over the free DOFs is " +
                          std::to_string(r.max_free_residual) + " (tolerance " +
                          std::to_string(r.tolerance) + "); residual by DOF:";
    for (std::size_t i = 0; i < r.q.size(); ++i) {
        char line[160];
        std::snprintf(line, sizeof line, "\n  %-16s q = %-14.8g F = %-12.4g%s",
                      view.dof_names[i].c_str(), r.q[i], r.residual[i],
                      r.held[i] ? (std::find(adjustment.balanced.begin(), adjustment.balanced.end(),
                                             static_cast<int>(i)) != adjustment.balanced.end()
                                       ? " (held, balanced)"
                                       : " (held)")
                                : "");
        message += line;
    }
    message += "\nA free DOF with a constant load and no stiffness has no equilibrium: hold it "
               "(--hold) or give it a rate.";
    throw UserError(message);
}

} // namespace yamsc::analysis
