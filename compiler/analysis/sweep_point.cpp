#include "analysis/sweep_point.hpp"

#include "analysis/load_blocks.hpp"
#include "analysis/trim_point.hpp"
#include "analysis/wind_input.hpp"
#include "diag/diagnostics.hpp"
#include "diag/errors.hpp"

#include <algorithm>

namespace yamsc::analysis {

using diag::UsageError;
using diag::UserError;
using driver::Assignment;
using driver::LinOptions;

using diag::UsageError;
using diag::UserError;

namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

} // namespace

SweepPoints::SweepPoints(const Loaded& l, const LinOptions& o) : l_(l), o_(o) {
    const std::string& name = o.sweep->name;
    const runtime::ModelView& v = l.view;
    if (!name.empty() && name.back() == '\'') {
        rate_dof_ = name.substr(0, name.size() - 1);
        if (!contains(v.dof_names, rate_dof_))
            throw UserError("--sweep: unknown DOF '" + rate_dof_ + "'" +
                            diag::did_you_mean(rate_dof_, v.dof_names));
    } else if (contains(v.input_names, name)) {
        input_ = name;
    } else {
        param_ = l.library->param_index(name);
        if (param_ < 0) {
            std::vector<std::string> names = l.library->param_names();
            names.insert(names.end(), v.input_names.begin(), v.input_names.end());
            throw UserError("--sweep: unknown parameter or input '" + name + "'" +
                            diag::did_you_mean(name, names) +
                            " (a rotor speed is swept as a rate: psi'=FROM:STEP:TO)");
        }
    }
    if (!input_.empty() && !o.wind.empty() &&
        v.input_names[static_cast<std::size_t>(wind_input(l, v))] == input_)
        throw UsageError("--sweep " + input_ + "=.. sets the wind: drop --wind");
    if (!o.schedule.empty()) schedule_ = read_sweep_schedule(o.schedule, name);
    if (any_blocks(block_options(o))) {
        if (param_ >= 0)
            throw UsageError("--sweep of the parameter " + name +
                             " with load blocks (--aero): a block is bound to the model's "
                             "parameters; sweep a rate or an input");
        blocks_view_ = with_load_blocks(l, linear_block_options(o));
        if (o.trim) trim_view_ = with_load_blocks(l, trim_block_options(o));
    }
}

SweepPoint SweepPoints::at(double value) const {
    std::vector<double> params = l_.params;
    if (param_ >= 0) params[static_cast<std::size_t>(param_)] = value;
    SweepPoint p{blocks_view_ ? *blocks_view_ : l_.library->view(params), {}, {}, {}};
    std::vector<Assignment> at = o_.at;
    if (schedule_) {
        const std::vector<Assignment> scheduled = schedule_at(*schedule_, value);
        at.insert(at.end(), scheduled.begin(), scheduled.end());
    }
    if (!rate_dof_.empty()) at.push_back({rate_dof_, 1, value});
    if (!input_.empty()) at.push_back({input_, 0, value});
    operating_point(l_, params, at, o_.u, p.q, p.qd, p.u);
    if (!o_.wind.empty()) set_wind_at_start(l_, p.view, p.u, o_.wind);
    if (o_.trim) {
        const runtime::TrimResult r =
            trim_point(trim_view_ ? *trim_view_ : p.view, p.q, p.qd, p.u, o_.hold, o_.adjust,
                       trim_settings(l_, block_options(o_)));
        p.q = r.q;
        p.u = r.u;
    }
    return p;
}

} // namespace yamsc::analysis
