// Co-simulation steps and snapshots of an instance (instance.hpp).
#include "instance.hpp"

#include "yamsc/cvode.hpp"
#include "yamsc/integration.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yamsc::fmi {

struct Snapshot {
    const Instance* owner = nullptr;
    Mode mode = Mode::instantiated;
    double t = 0.0;
    std::vector<double> x, u, p;
    runtime::Method method = runtime::Method::rk4;
    double step = 0.0;
    std::optional<double> tolerance;
    std::optional<runtime::Abm4Integrator> abm4;
    double t_accepted = 0.0;
    std::vector<double> x_accepted, u_accepted;
};

runtime::OdeFunction Instance::ode() {
    return [this](double t, const double* x, double* xdot) { view_.rhs(t, x, u_.data(), xdot); };
}

// One internal step of RK4 or ABM4 from t, then the view's projection onto
// its constraints and its blocks' discrete update, as runtime::simulate does.
void Instance::step_fixed(double t, double dt) {
    const std::size_t n = x_.size();
    const std::vector<double> x_start = view_.update_discrete ? x_ : std::vector<double>();
    if (method_ == runtime::Method::rk4) {
        if (!rk4_ || rk4_->size() != n) rk4_.emplace(n);
        runtime::rk4_step(ode(), t, dt, x_.data(), *rk4_);
    } else {
        if (!abm4_) abm4_.emplace(ode(), n);
        abm4_->step(t, dt, x_.data());
    }
    for (double v : x_)
        if (!std::isfinite(v)) {
            std::ostringstream msg;
            msg << "the state is no longer finite at t = " << t + dt << " s ("
                << runtime::method_name(method_) << " with the step " << dt
                << " s): the step may be too large for the model's fastest mode";
            throw std::runtime_error(msg.str());
        }
    if (view_.project) view_.project(t + dt, x_.data(), u_.data());
    if (view_.update_discrete)
        view_.update_discrete(t, x_start.data(), u_.data(), t + dt, x_.data(), u_.data());
}

// CVODE from t to t_end, restarted at t (the communication point: inputs may
// have changed there); yamsc.step > 0 bounds its internal steps.
void Instance::step_cvode(double t, double t_end) {
    runtime::CvodeOptions options;
    // The host's tolerance is relative; the absolute one follows it at the
    // states' nominal value 1 (GetNominalsOfContinuousStates).
    if (tolerance_) options.rtol = options.atol = *tolerance_;
    options.max_step = step_;
    const std::vector<double> x_start = x_;
    runtime::simulate_cvode(
        view_, x_start, u_, t_end, t_end - t,
        [this](double, const double* x) {
            std::copy(x, x + x_.size(), x_.begin());
            return true;
        },
        options, t);
    if (view_.update_discrete)
        view_.update_discrete(t, x_start.data(), u_.data(), t_end, x_.data(), u_.data());
}

Status Instance::do_step(double t, double h) {
    if (!allowed("DoStep", {Mode::step})) return Status::error;
    if (!(std::abs(t - t_) <= 1e-9 * std::max(1.0, std::abs(t_)))) {
        std::ostringstream msg;
        msg.precision(17);
        msg << "DoStep: the communication point " << t << " s is not the instance's time " << t_
            << " s";
        return fail(msg.str());
    }
    if (!(h >= 0.0) || !std::isfinite(h))
        return fail("DoStep: the communication step must not be negative");
    if (h == 0.0) return Status::ok;
    refresh_view();
    const double t_end = t + h;
    if (method_ == runtime::Method::cvode) {
        step_cvode(t, t_end);
    } else {
        // The runtime's grid: steps of yamsc.step from t, the last one shortened
        // to land on t + h (equal to runtime::simulate's steps when h is the step).
        const runtime::TimeGrid grid(t, t_end, step_);
        for (std::size_t k = 1; k < grid.size(); ++k)
            step_fixed(grid[k - 1], grid[k] - grid[k - 1]);
    }
    t_ = t_end;
    changed(false);
    return Status::ok;
}

Status Instance::get_state(Snapshot** state) {
    if (view_.update_discrete)
        return fail(
            "GetFMUState: the model's load blocks hold discrete states a snapshot cannot copy");
    Snapshot* s = *state ? *state : new Snapshot;
    s->owner = this;
    s->mode = mode_;
    s->t = t_;
    s->x = x_;
    s->u = u_;
    s->p = p_;
    s->method = method_;
    s->step = step_;
    s->tolerance = tolerance_;
    s->abm4 = abm4_;
    s->t_accepted = t_accepted_;
    s->x_accepted = x_accepted_;
    s->u_accepted = u_accepted_;
    *state = s;
    return Status::ok;
}

Status Instance::set_state(const Snapshot* s) {
    if (!s) return fail("SetFMUState: no state given");
    if (s->x.size() != x_.size() || s->u.size() != u_.size() || s->p.size() != p_.size())
        return fail("SetFMUState: the state belongs to another model");
    mode_ = s->mode;
    t_ = s->t;
    x_ = s->x;
    u_ = s->u;
    if (p_ != s->p) view_stale_ = true;
    p_ = s->p;
    if (p_ != view_params_) view_stale_ = true;
    method_ = s->method;
    step_ = s->step;
    tolerance_ = s->tolerance;
    t_accepted_ = s->t_accepted;
    x_accepted_ = s->x_accepted;
    u_accepted_ = s->u_accepted;
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
