#include "yamsc/integration.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace yamsc::runtime {

namespace {
// A grid this long would not fit in memory once stored; refuse it up front.
constexpr double max_grid_intervals = 1e8;
// Interval counts within this many steps of an integer are taken as that
// integer, so that rounding in (t_end - t_start) / dt does not add a sliver step.
constexpr double step_count_slack = 1e-6;

std::string number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}
} // namespace

InputFunction constant_input(std::vector<double> u) {
    return [u = std::move(u)](double, double* out) {
        for (std::size_t i = 0; i < u.size(); ++i) out[i] = u[i];
    };
}

TimeGrid::TimeGrid(double t_start, double t_end, double dt)
    : t_start_(t_start), t_end_(t_end), dt_(dt), count_(1) {
    if (!std::isfinite(t_start) || !std::isfinite(t_end))
        throw std::invalid_argument("start and end times must be finite");
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw std::invalid_argument("time step must be positive, got " + number(dt));
    if (t_end < t_start)
        throw std::invalid_argument("end time " + number(t_end) + " is before the start time " +
                                    number(t_start));
    const double intervals = std::ceil((t_end - t_start) / dt - step_count_slack);
    if (intervals > max_grid_intervals)
        throw std::invalid_argument("more than 1e8 time steps: increase the time step or "
                                    "shorten the simulation");
    count_ = static_cast<std::size_t>(std::max(intervals, 0.0)) + 1;
}

double TimeGrid::operator[](std::size_t k) const {
    if (k + 1 >= count_) return t_end_;
    return t_start_ + static_cast<double>(k) * dt_;
}

std::string state_name(const ModelView& view, int i) {
    if (i < 0 || i >= view.nx()) return "state " + std::to_string(i);
    if (i >= 2 * view.nq) {
        const auto k = static_cast<std::size_t>(i - 2 * view.nq);
        return k < view.block_state_names.size() ? view.block_state_names[k]
                                                 : "state " + std::to_string(i);
    }
    const auto dof = static_cast<std::size_t>(i % view.nq);
    const std::string name =
        dof < view.dof_names.size() ? view.dof_names[dof] : "q" + std::to_string(dof);
    return i < view.nq ? name : name + "'";
}

void check_initial_state(const ModelView& view, const std::vector<double>& x0) {
    if (x0.size() != static_cast<std::size_t>(view.nx()))
        throw std::invalid_argument("initial state has " + std::to_string(x0.size()) +
                                    " values, the model needs " + std::to_string(view.nx()) +
                                    " (its DOFs, their rates and its load blocks' states)");
    for (std::size_t i = 0; i < x0.size(); ++i)
        if (!std::isfinite(x0[i]))
            throw std::invalid_argument("initial value of " +
                                        state_name(view, static_cast<int>(i)) + " is not finite");
}

void check_input_size(const ModelView& view, const std::vector<double>& u) {
    if (u.size() != static_cast<std::size_t>(view.nu))
        throw std::invalid_argument("got " + std::to_string(u.size()) +
                                    " input values, the model has " + std::to_string(view.nu) +
                                    " inputs");
}

} // namespace yamsc::runtime
