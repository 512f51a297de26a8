#pragma once
// Simulation results as CSV (one header row of column names, then one row per
// output time) and as a short text summary for the terminal.
#include "yamsc/simulation.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace yamsc::runtime {

/// Significant digits of every CSV value: enough to reproduce the run's
/// numbers far below any physical tolerance, short enough to stay readable.
inline constexpr int csv_significant_digits = 10;

/// One value as written in the CSV (shortest of fixed/scientific, like %.10g,
/// independent of the C locale).
std::string format_csv_value(double value);
/// The same text appended to `out` without a temporary string: what the CSV
/// writers call once per value.
void append_csv_value(std::string& out, double value);

void write_csv(const SimulationResult& result, std::ostream& out);
/// Writes atomically (see atomic_file.hpp); throws std::runtime_error on failure.
void write_csv(const SimulationResult& result, const std::string& path);

struct ChannelSummary {
    std::string name;
    double min = 0.0, max = 0.0, final = 0.0;
};

/// Min, max and final value of every column but time; empty for an empty result.
std::vector<ChannelSummary> summarize(const SimulationResult& result);

/// A table: one line per channel with min, max and final value, preceded by a
/// line with the number of rows and the time span.
std::string format_summary(const SimulationResult& result);

} // namespace yamsc::runtime
