#pragma once
// Fixed-step Adams-Bashforth-Moulton, fourth order (ABM4): the integrator of
// OpenFAST's ElastoDyn (Method = 3). Two right-hand sides per step instead of
// RK4's four, so at the same step it costs half as much; its stability region
// is smaller than RK4's, enough for the step sizes the aeroelastic decks use.
#include "yamsc/integration.hpp"
#include "yamsc/model_view.hpp"
#include "yamsc/rk4.hpp"

#include <cstddef>
#include <vector>

namespace yamsc::runtime {

/// The derivative history and buffers of an ABM4 run, allocated once.
class Abm4Integrator {
public:
    /// n states; f is called as f(t, x, xdot).
    Abm4Integrator(OdeFunction f, std::size_t n);

    /// Advances x from t to t + dt in place. The first three steps, and any
    /// step whose length differs from the previous one (a shortened last step),
    /// are RK4 steps: multistep formulas need an equally spaced history. From
    /// the fourth step on: the AB4 predictor from f at the last four points,
    /// f at the predicted point, the AM4 corrector (PECE, as ElastoDyn's
    /// ED_ABM4); f at the corrected point starts the next step. f_start, when
    /// given, is f(t, x) already evaluated: the step does not call f for it.
    void step(double t, double dt, double* x, const double* f_start = nullptr);

    /// How many past derivatives the next step can use (0-4); 3 or more: an ABM4 step.
    std::size_t history() const { return filled_; }

private:
    OdeFunction f_;
    std::size_t n_;
    // f at t_n, t_{n-1}, t_{n-2}, t_{n-3}; rotated, not copied.
    std::vector<double> hist_[4];
    std::size_t newest_ = 0; // index of f(t_n) in hist_
    std::size_t filled_ = 0; // how many of hist_ are valid for the current step length
    double dt_ = 0.0;
    std::vector<double> predicted_, f_predicted_;
    Rk4Workspace rk4_;

    const double* past(std::size_t age) const { return hist_[(newest_ + 4 - age) % 4].data(); }
};

/// Integrates the view as simulate_rk4 does (same grid, observer, inputs at
/// the evaluation times, exceptions) with ABM4.
std::size_t simulate_abm4(const ModelView& view, const std::vector<double>& x0,
                          const InputFunction& u, double t_end, double dt,
                          const StateObserver& observe, double t_start = 0.0);

} // namespace yamsc::runtime
