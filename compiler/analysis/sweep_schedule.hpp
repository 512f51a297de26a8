#pragma once
// Operating points along a sweep (`lin --sweep NAME=.. --schedule FILE`): the
// swept value, and what else changes with it. A Campbell diagram over wind
// speed needs the rotor speed and the controller's torque and pitch at each
// wind speed, which a steady-state table gives (OpenFAST users take it from a
// previous run or from the controller's tuning). The schedule is a CSV whose
// first column is the swept name and whose other columns name DOFs (`q`),
// rates (`psi'`) or inputs, as `--at` does; rows rise in the swept value and
// are interpolated linearly between them.
#include "analysis/channels.hpp"
#include "driver/values.hpp"

#include <string>
#include <vector>

namespace yamsc::analysis {

struct SweepSchedule {
    std::string path;
    Table table; // column 0: the swept value
};

/// Reads `path` for a sweep of `swept`: UserError (path:line) unless the first
/// column is named `swept`, rises, and has at least two rows.
SweepSchedule read_sweep_schedule(const std::string& path, const std::string& swept);

/// The schedule's other columns at `value`, as `--at` assignments (linear
/// interpolation). UserError when `value` lies outside the schedule.
std::vector<driver::Assignment> schedule_at(const SweepSchedule& s, double value);

} // namespace yamsc::analysis
