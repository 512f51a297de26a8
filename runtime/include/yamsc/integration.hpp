#pragma once
// What every integrator of the runtime shares: input signals, the observer that
// receives the states, and the output time grid.
#include "yamsc/model_view.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace yamsc::runtime {

/// Writes the nu input values at time t into u.
using InputFunction = std::function<void(double t, double* u)>;

/// An input that does not change with time.
InputFunction constant_input(std::vector<double> u);

/// Receives the state x (2 nq values, [q, q']) at each output time; returning
/// false stops the integration after this point.
using StateObserver = std::function<bool(double t, const double* x)>;

/// Output times t_start, t_start + dt, ..., always ending exactly at t_end: a
/// last step shorter than dt is taken when dt does not divide the interval.
/// Times are computed as t_start + k dt (not accumulated) so that long runs do
/// not drift off the grid.
class TimeGrid {
public:
    /// Throws std::invalid_argument unless dt > 0, t_end >= t_start and both are finite.
    TimeGrid(double t_start, double t_end, double dt);

    std::size_t size() const { return count_; }
    double operator[](std::size_t k) const;
    double step() const { return dt_; }

private:
    double t_start_, t_end_, dt_;
    std::size_t count_;
};

/// The name of state i: the DOF name for i < nq, the DOF name and a prime for its rate.
std::string state_name(const ModelView& view, int i);

/// Throws std::invalid_argument naming the problem unless x0 has 2 nq finite values.
void check_initial_state(const ModelView& view, const std::vector<double>& x0);
/// Throws std::invalid_argument unless u has nu values.
void check_input_size(const ModelView& view, const std::vector<double>& u);

} // namespace yamsc::runtime
