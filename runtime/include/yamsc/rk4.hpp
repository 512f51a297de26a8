#pragma once
// Fixed-step classical Runge-Kutta (RK4): predictable cost per step, what a
// real-time simulator or a controller-in-the-loop test needs.
#include "yamsc/integration.hpp"
#include "yamsc/model_view.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace yamsc::runtime {

/// dx/dt = f(t, x), written into xdot.
using OdeFunction = std::function<void(double t, const double* x, double* xdot)>;

/// The stage buffers of one RK4 step, allocated once per run.
class Rk4Workspace {
public:
    explicit Rk4Workspace(std::size_t n) : k1(n), k2(n), k3(n), k4(n), stage(n) {}
    std::size_t size() const { return k1.size(); }

    std::vector<double> k1, k2, k3, k4, stage;
};

/// Advances x (work.size() values) from t to t + dt in place. f_start, when
/// given, is f(t, x) already evaluated (the step then calls f three times).
void rk4_step(const OdeFunction& f, double t, double dt, double* x, Rk4Workspace& work,
              const double* f_start = nullptr);
/// Convenience form that allocates its own workspace.
void rk4_step(const OdeFunction& f, double t, double dt, std::vector<double>& x);

/// Integrates the view from x0 at t_start to t_end with steps of dt (the last
/// one shortened to land on t_end), calling `observe` at t_start and after every
/// step. The inputs are evaluated at the stage times. Returns the number of
/// steps taken. Throws std::invalid_argument on bad arguments and
/// std::runtime_error when the state stops being finite (step too large or an
/// unstable model), naming the time.
std::size_t simulate_rk4(const ModelView& view, const std::vector<double>& x0,
                         const InputFunction& u, double t_end, double dt,
                         const StateObserver& observe, double t_start = 0.0);
/// The same with constant inputs (nu values).
std::size_t simulate_rk4(const ModelView& view, const std::vector<double>& x0,
                         const std::vector<double>& u, double t_end, double dt,
                         const StateObserver& observe, double t_start = 0.0);

} // namespace yamsc::runtime
