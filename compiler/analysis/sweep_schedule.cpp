#include "analysis/sweep_schedule.hpp"

#include "analysis/compare.hpp"
#include "diag/errors.hpp"

#include <algorithm>
#include <cstdio>

namespace yamsc::analysis {

using diag::UserError;
using driver::Assignment;

using diag::UserError;

SweepSchedule read_sweep_schedule(const std::string& path, const std::string& swept) {
    SweepSchedule s{path, read_table(path)};
    // read_table checks that the first column rises, row by row.
    if (s.table.columns.front() != swept)
        throw UserError(path + ":1: the schedule's first column is '" + s.table.columns.front() +
                        "'; a sweep of " + swept + " needs it to be '" + swept + "'");
    if (s.table.rows() < 2)
        throw UserError(path + ": a schedule needs at least two rows to interpolate between");
    return s;
}

std::vector<Assignment> schedule_at(const SweepSchedule& s, double value) {
    const std::vector<double>& x = s.table.data.front();
    if (value < x.front() || value > x.back()) {
        char range[160];
        std::snprintf(range, sizeof range, "%s = %g lies outside the schedule (%g to %g)",
                      s.table.columns.front().c_str(), value, x.front(), x.back());
        throw UserError(s.path + ": " + range);
    }
    // The interval [x[k-1], x[k]] that holds value.
    const std::size_t k = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::lower_bound(x.begin(), x.end(), value) - x.begin()));
    const double w = (value - x[k - 1]) / (x[k] - x[k - 1]);
    std::vector<Assignment> at;
    for (std::size_t j = 1; j < s.table.columns.size(); ++j) {
        std::string name = s.table.columns[j];
        int primes = 0;
        while (!name.empty() && name.back() == '\'') {
            name.pop_back();
            ++primes;
        }
        const std::vector<double>& y = s.table.data[j];
        at.push_back({name, primes, y[k - 1] + w * (y[k] - y[k - 1])});
    }
    return at;
}

} // namespace yamsc::analysis
