// Co-simulation steps and snapshots of an instance (instance.hpp).
#include "instance.hpp"

#include "yamsc/cvode.hpp"
#include "yamsc/integration.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yamsc::fmi {

runtime::OdeFunction Instance::ode() {
    return [this](double t, const double* x, double* xdot) { view_.rhs(t, x, n_.u.data(), xdot); };
}

// One internal step of RK4 or ABM4 from t, then the view's projection onto
// its constraints and its blocks' discrete update, as runtime::simulate does.
void Instance::step_fixed(double t, double dt) {
    const std::size_t n = n_.x.size();
    const std::vector<double> x_start = view_.update_discrete ? n_.x : std::vector<double>();
    if (n_.method == runtime::Method::rk4) {
        if (!rk4_ || rk4_->size() != n) rk4_.emplace(n);
        runtime::rk4_step(ode(), t, dt, n_.x.data(), *rk4_);
    } else {
        if (!abm4_) abm4_.emplace(ode(), n);
        abm4_->step(t, dt, n_.x.data());
    }
    for (double v : n_.x)
        if (!std::isfinite(v)) {
            std::ostringstream msg;
            msg << "the state is no longer finite at t = " << t + dt << " s ("
                << runtime::method_name(n_.method) << " with the step " << dt
                << " s): the step may be too large for the model's fastest mode";
            throw std::runtime_error(msg.str());
        }
    if (view_.project) view_.project(t + dt, n_.x.data(), n_.u.data());
    if (view_.update_discrete)
        view_.update_discrete(t, x_start.data(), n_.u.data(), t + dt, n_.x.data(), n_.u.data());
}

// CVODE from t to t_end, restarted at t (the communication point: inputs may
// have changed there); yamsc.step > 0 bounds its internal steps.
void Instance::step_cvode(double t, double t_end) {
    runtime::CvodeOptions options;
    // The host's tolerance is relative; the absolute one follows it at the
    // states' nominal value 1 (GetNominalsOfContinuousStates).
    if (n_.tolerance) options.rtol = options.atol = *n_.tolerance;
    options.max_step = n_.step;
    const std::vector<double> x_start = n_.x;
    runtime::simulate_cvode(
        view_, x_start, n_.u, t_end, t_end - t,
        [this](double, const double* x) {
            std::copy(x, x + n_.x.size(), n_.x.begin());
            return true;
        },
        options, t);
    if (view_.update_discrete)
        view_.update_discrete(t, x_start.data(), n_.u.data(), t_end, n_.x.data(), n_.u.data());
}

Status Instance::do_step(double t, double h) {
    if (!allowed("DoStep", {Mode::step})) return Status::error;
    if (!(std::abs(t - n_.t) <= 1e-9 * std::max(1.0, std::abs(n_.t)))) {
        std::ostringstream msg;
        msg.precision(17);
        msg << "DoStep: the communication point " << t << " s is not the instance's time " << n_.t
            << " s";
        return fail(msg.str());
    }
    if (!(h >= 0.0) || !std::isfinite(h))
        return fail("DoStep: the communication step must not be negative");
    if (h == 0.0) return Status::ok;
    refresh_view();
    const double t_end = t + h;
    if (n_.method == runtime::Method::cvode) {
        step_cvode(t, t_end);
    } else {
        // The runtime's grid: steps of yamsc.step from t, the last one shortened
        // to land on t + h (equal to runtime::simulate's steps when h is the step).
        const runtime::TimeGrid grid(t, t_end, n_.step);
        for (std::size_t k = 1; k < grid.size(); ++k)
            step_fixed(grid[k - 1], grid[k] - grid[k - 1]);
    }
    n_.t = t_end;
    changed(false);
    return Status::ok;
}

Status Instance::get_state(Snapshot** state) {
    if (view_.update_discrete)
        return fail(
            "GetFMUState: the model's load blocks hold discrete states a snapshot cannot copy");
    Snapshot* s = *state ? *state : new Snapshot;
    s->owner = this;
    s->interface = interface_;
    s->numbers = n_;
    s->abm4 = abm4_;
    *state = s;
    return Status::ok;
}

Status Instance::set_state(const Snapshot* s) {
    if (!s) return fail("SetFMUState: no state given");
    if (s->interface != interface_)
        return fail(
            "SetFMUState: the state is of another interface (model exchange, co-simulation)");
    const Numbers& m = s->numbers;
    if (m.x.size() != n_.x.size() || m.u.size() != n_.u.size() || m.p.size() != n_.p.size())
        return fail("SetFMUState: the state belongs to another model");
    n_ = m;
    if (n_.p != view_params_) view_stale_ = true;
    xdot_known_ = y_known_ = false;
    // ABM4's history evaluates this instance's right-hand side: kept for its own snapshots.
    if (s->owner == this && !view_stale_)
        abm4_ = s->abm4;
    else
        abm4_.reset();
    return Status::ok;
}

void Instance::free_state(Snapshot* state) {
    delete state;
}

} // namespace yamsc::fmi
