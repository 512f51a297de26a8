#include "yamsc/abm4.hpp"

#include "fixed_step.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace yamsc::runtime {

namespace {
// Steps whose lengths differ by less than this (relative) share a history: the
// grid's steps t_start + k dt differ from each other by rounding only.
constexpr double same_step = 1e-9;
} // namespace

Abm4Integrator::Abm4Integrator(OdeFunction f, std::size_t n)
    : f_(std::move(f)), n_(n), predicted_(n), f_predicted_(n), rk4_(n) {
    for (auto& h : hist_) h.assign(n, 0.0);
}

void Abm4Integrator::step(double t, double dt, double* x, const double* f_start) {
    if (filled_ > 0 && std::abs(dt - dt_) > same_step * std::abs(dt_)) filled_ = 0;
    if (filled_ == 0) dt_ = dt;
    if (filled_ < 3) {
        // The start: RK4, whose first stage is f(t_n, x_n), kept for the history.
        rk4_step(f_, t, dt, x, rk4_, f_start);
        newest_ = (newest_ + 1) % 4;
        hist_[newest_] = rk4_.k1;
        ++filled_;
        return;
    }
    newest_ = (newest_ + 1) % 4;
    if (f_start)
        std::copy(f_start, f_start + n_, hist_[newest_].begin());
    else
        f_(t, x, hist_[newest_].data());
    if (filled_ < 4) ++filled_;
    const double* f0 = past(0);
    const double* f1 = past(1);
    const double* f2 = past(2);
    const double* f3 = past(3);
    const double h24 = dt / 24.0;
    // Predictor (AB4) and corrector (AM4), the coefficients of ElastoDyn's ED_AB4/ED_ABM4.
    for (std::size_t i = 0; i < n_; ++i)
        predicted_[i] = x[i] + h24 * (55.0 * f0[i] - 59.0 * f1[i] + 37.0 * f2[i] - 9.0 * f3[i]);
    f_(t + dt, predicted_.data(), f_predicted_.data());
    for (std::size_t i = 0; i < n_; ++i)
        x[i] += h24 * (9.0 * f_predicted_[i] + 19.0 * f0[i] - 5.0 * f1[i] + f2[i]);
}

std::size_t detail::simulate_abm4_observing(const ModelView& view, const std::vector<double>& x0,
                                            const InputFunction& u, double t_end, double dt,
                                            const DerivativeObserver& observe, double t_start) {
    return simulate_fixed_step(
        "ABM4", view, x0, u, t_end, dt, observe, t_start, [](const OdeFunction& f, std::size_t n) {
            return [integrator = Abm4Integrator(f, n)](double t, double h, double* x,
                                                       const double* f_start) mutable {
                integrator.step(t, h, x, f_start);
            };
        });
}

std::size_t simulate_abm4(const ModelView& view, const std::vector<double>& x0,
                          const InputFunction& u, double t_end, double dt,
                          const StateObserver& observe, double t_start) {
    return detail::simulate_abm4_observing(view, x0, u, t_end, dt,
                                           detail::ignoring_derivative(observe), t_start);
}

} // namespace yamsc::runtime
