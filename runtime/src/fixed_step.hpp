#pragma once
// The loop shared by the fixed-step integrators (rk4.cpp, abm4.cpp): argument
// checks, the time grid, inputs at the evaluation times, the observer after
// every step and the divergence check. Internal to the runtime.
#include "yamsc/integration.hpp"
#include "yamsc/model_view.hpp"
#include "yamsc/rk4.hpp"

#include <cmath>
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

/// make(f, n) returns the stepper: a callable step(t, dt, x) advancing x in place.
template <class MakeStepper>
std::size_t simulate_fixed_step(const char* method, const ModelView& view,
                                const std::vector<double>& x0, const InputFunction& u, double t_end,
                                double dt, const StateObserver& observe, double t_start,
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

    std::vector<double> x = x0;
    auto stepper = make(f, x.size());
    if (observe && !observe(grid[0], x.data())) return 0;
    for (std::size_t k = 1; k < grid.size(); ++k) {
        const double t = grid[k - 1];
        stepper(t, grid[k] - t, x.data());
        if (!all_finite(x)) throw_diverged(method, grid[k], dt);
        if (observe && !observe(grid[k], x.data())) return k;
    }
    return grid.size() - 1;
}

} // namespace yamsc::runtime::detail
