#include "yamsc/rk4.hpp"

#include "fixed_step.hpp"

#include <algorithm>

namespace yamsc::runtime {

void rk4_step(const OdeFunction& f, double t, double dt, double* x, Rk4Workspace& work,
              const double* f_start) {
    const std::size_t n = work.size();
    double* stage = work.stage.data();
    const double half = 0.5 * dt;

    if (f_start)
        std::copy(f_start, f_start + n, work.k1.begin());
    else
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

std::size_t detail::simulate_rk4_observing(const ModelView& view, const std::vector<double>& x0,
                                           const InputFunction& u, double t_end, double dt,
                                           const DerivativeObserver& observe, double t_start) {
    return simulate_fixed_step(
        "RK4", view, x0, u, t_end, dt, observe, t_start, [](const OdeFunction& f, std::size_t n) {
            return [&f, work = Rk4Workspace(n)](double t, double h, double* x,
                                                const double* f_start) mutable {
                rk4_step(f, t, h, x, work, f_start);
            };
        });
}

std::size_t simulate_rk4(const ModelView& view, const std::vector<double>& x0,
                         const InputFunction& u, double t_end, double dt,
                         const StateObserver& observe, double t_start) {
    return detail::simulate_rk4_observing(view, x0, u, t_end, dt,
                                          detail::ignoring_derivative(observe), t_start);
}

std::size_t simulate_rk4(const ModelView& view, const std::vector<double>& x0,
                         const std::vector<double>& u, double t_end, double dt,
                         const StateObserver& observe, double t_start) {
    check_input_size(view, u);
    return simulate_rk4(view, x0, constant_input(u), t_end, dt, observe, t_start);
}

} // namespace yamsc::runtime
