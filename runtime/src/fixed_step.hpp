#pragma once
// The loop shared by the fixed-step integrators (rk4.cpp, abm4.cpp): argument
// checks, the time grid, inputs at the evaluation times, the observer after
// every step and the divergence check. Internal to the runtime.
#include "yamsc/integration.hpp"
#include "yamsc/model_view.hpp"
#include "yamsc/rk4.hpp"

#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace yamsc::runtime::detail {

inline bool all_finite(const std::vector<double>& x) {
    for (double v : x)
        if (!std::isfinite(v)) return false;
    return true;
}

[[noreturn]] inline void throw_diverged(const char* method, double t, double dt) {
    std::ostringstream msg;
    msg << "the state is no longer finite at t = " << t << " s (" << method << " with dt = " << dt
        << " s): the step may be too large for the model's fastest mode, or the model is "
           "unstable";
    throw std::runtime_error(msg.str());
}

/// f(t, x) at the point the observer sees, computed only if the observer asks
/// for it, and then handed to the next step, whose first stage is that same
/// call (RK4's k1, ABM4's newest derivative): a row's outputs can use its q''
/// (ModelView::outputs_from_qdd) without another right-hand side.
class PointDerivative {
public:
    PointDerivative(const OdeFunction& f, std::size_t n) : f_(f), value_(n) {}

    /// The point (x is read when the derivative is asked for, not copied).
    void move_to(double t, const double* x) {
        t_ = t;
        x_ = x;
        known_ = false;
    }
    /// x' = f(t, x), evaluated on the first call at this point.
    const double* operator()() {
        if (!known_) {
            f_(t_, x_, value_.data());
            known_ = true;
        }
        return value_.data();
    }
    /// x' if it has been evaluated at this point, else null.
    const double* known() const { return known_ ? value_.data() : nullptr; }

private:
    const OdeFunction& f_;
    std::vector<double> value_;
    double t_ = 0.0;
    const double* x_ = nullptr;
    bool known_ = false;
};

/// An observer that may ask for x' at the point it receives.
using DerivativeObserver =
    std::function<bool(double t, const double* x, PointDerivative& derivative)>;

inline DerivativeObserver ignoring_derivative(const StateObserver& observe) {
    if (!observe) return {};
    return [&observe](double t, const double* x, PointDerivative&) { return observe(t, x); };
}

/// make(f, n) returns the stepper: a callable step(t, dt, x, f_start) advancing
/// x in place, f_start = f(t, x) when known, else null.
template <class MakeStepper>
std::size_t simulate_fixed_step(const char* method, const ModelView& view,
                                const std::vector<double>& x0, const InputFunction& u, double t_end,
                                double dt, const DerivativeObserver& observe, double t_start,
                                MakeStepper make) {
    check_initial_state(view, x0);
    if (!view.rhs) throw std::invalid_argument("the model view has no right-hand side");
    if (view.nu > 0 && !u) throw std::invalid_argument("the model has inputs but none were given");
    const TimeGrid grid(t_start, t_end, dt);

    std::vector<double> u_now(static_cast<std::size_t>(view.nu));
    const OdeFunction f = [&](double t, const double* x, double* xdot) {
        if (view.nu > 0) u(t, u_now.data());
        view.rhs(t, x, u_now.data(), xdot);
    };

    std::vector<double> x = x0, x_start;
    std::vector<double> u_start(static_cast<std::size_t>(view.nu)), u_end(u_start.size());
    auto stepper = make(f, x.size());
    PointDerivative derivative(f, x.size());
    derivative.move_to(grid[0], x.data());
    if (observe && !observe(grid[0], x.data(), derivative)) return 0;
    for (std::size_t k = 1; k < grid.size(); ++k) {
        const double t = grid[k - 1];
        if (view.update_discrete) x_start = x;
        stepper(t, grid[k] - t, x.data(), derivative.known());
        if (!all_finite(x)) throw_diverged(method, grid[k], dt);
        if (view.nu > 0 && (view.project || view.update_discrete)) u(grid[k], u_end.data());
        // Back onto the constraints. ABM4's history needs nothing: each step's
        // newest derivative is evaluated at its start, the projected point.
        if (view.project) view.project(grid[k], x.data(), u_end.data());
        if (view.update_discrete) {
            // The blocks' discrete states, from t to grid[k] (load_block.hpp).
            if (view.nu > 0) u(t, u_start.data());
            view.update_discrete(t, x_start.data(), u_start.data(), grid[k], x.data(),
                                 u_end.data());
        }
        derivative.move_to(grid[k], x.data());
        if (observe && !observe(grid[k], x.data(), derivative)) return k;
    }
    return grid.size() - 1;
}

/// simulate_rk4 and simulate_abm4 with an observer that may ask for x'
/// (simulate() stores the outputs with it).
std::size_t simulate_rk4_observing(const ModelView& view, const std::vector<double>& x0,
                                   const InputFunction& u, double t_end, double dt,
                                   const DerivativeObserver& observe, double t_start);
std::size_t simulate_abm4_observing(const ModelView& view, const std::vector<double>& x0,
                                    const InputFunction& u, double t_end, double dt,
                                    const DerivativeObserver& observe, double t_start);

} // namespace yamsc::runtime::detail
