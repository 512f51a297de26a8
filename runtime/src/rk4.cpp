#include "yamsc/rk4.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yamsc::runtime {

void rk4_step(const OdeFunction& f, double t, double dt, double* x, Rk4Workspace& work) {
    const std::size_t n = work.size();
    double* stage = work.stage.data();
    const double half = 0.5 * dt;

    f(t, x, work.k1.data());
    for (std::size_t i = 0; i < n; ++i) stage[i] = x[i] + half * work.k1[i];
    f(t + half, stage, work.k2.data());
    for (std::size_t i = 0; i < n; ++i) stage[i] = x[i] + half * work.k2[i];
    f(t + half, stage, work.k3.data());
    for (std::size_t i = 0; i < n; ++i) stage[i] = x[i] + dt * work.k3[i];
    f(t + dt, stage, work.k4.data());
    for (std::size_t i = 0; i < n; ++i)
        x[i] += dt / 6.0 * (work.k1[i] + 2.0 * (work.k2[i] + work.k3[i]) + work.k4[i]);
}

void rk4_step(const OdeFunction& f, double t, double dt, std::vector<double>& x) {
    Rk4Workspace work(x.size());
    rk4_step(f, t, dt, x.data(), work);
}

namespace {

bool all_finite(const std::vector<double>& x) {
    for (double v : x)
        if (!std::isfinite(v)) return false;
    return true;
}

[[noreturn]] void throw_diverged(double t, double dt) {
    std::ostringstream msg;
    msg << "the state is no longer finite at t = " << t << " s (RK4 with dt = " << dt
        << " s): the step may be too large for the model's fastest mode, or the model is "
           "unstable";
    throw std::runtime_error(msg.str());
}

} // namespace

std::size_t simulate_rk4(const ModelView& view, const std::vector<double>& x0,
                         const InputFunction& u, double t_end, double dt,
                         const StateObserver& observe, double t_start) {
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
    Rk4Workspace work(x.size());
    if (observe && !observe(grid[0], x.data())) return 0;
    for (std::size_t k = 1; k < grid.size(); ++k) {
        const double t = grid[k - 1];
        rk4_step(f, t, grid[k] - t, x.data(), work);
        if (!all_finite(x)) throw_diverged(grid[k], dt);
        if (observe && !observe(grid[k], x.data())) return k;
    }
    return grid.size() - 1;
}

std::size_t simulate_rk4(const ModelView& view, const std::vector<double>& x0,
                         const std::vector<double>& u, double t_end, double dt,
                         const StateObserver& observe, double t_start) {
    check_input_size(view, u);
    return simulate_rk4(view, x0, constant_input(u), t_end, dt, observe, t_start);
}

} // namespace yamsc::runtime
