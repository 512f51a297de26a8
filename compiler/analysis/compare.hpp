#pragma once
// A simulation against a reference time series (an OpenFAST output converted to
// CSV, or any table with a time column): the reference's channels found in the
// simulation are interpolated onto common times and scored.
#include "analysis/channels.hpp"

#include <string>
#include <vector>

namespace yamsc::analysis {

/// Reads a time series (formats/table: CSV or an OpenFAST `.out`; column 0 is
/// time, rising). Throws UserError with the file and line on bad input.
Table read_table(const std::string& path);

struct ChannelScore {
    std::string name;          ///< the reference's column name
    std::string matched;       ///< the simulation's column compared with it
    std::size_t samples = 0;   ///< common times compared
    double range = 0;          ///< max - min of the reference over those times
    double mean_rel_error = 0; ///< mean |sim - ref| / range, a fraction (not percent)
    double max_abs_error = 0;
    double r2 = 0; ///< 1 - sum (sim - ref)^2 / sum (ref - mean ref)^2
};

struct Comparison {
    std::vector<ChannelScore> channels;
    std::vector<std::string> missing; ///< reference channels the simulation lacks
    double t_begin = 0, t_end = 0;    ///< the common time span
};

/// Scores every channel of `reference` (but time) that `simulation` has, by exact
/// name or by name without the unit suffix (`Q_TFA1_[m]` ~ `Q_TFA1`). The simulation
/// is linearly interpolated onto the reference times within the common span.
/// Channels named `Azimuth` are unwrapped (jumps over 180 deg) in both first, so that
/// a wrap at 360 deg is not scored as an error. Throws UserError when the spans do
/// not overlap.
Comparison compare_tables(const Table& simulation, const Table& reference);

/// A table for the terminal: channel, mean relative error [%], max error, R².
std::string format_comparison(const Comparison& c, const std::string& reference_name);

/// `values` unwrapped: consecutive jumps larger than half of `period` are removed.
std::vector<double> unwrap(std::vector<double> values, double period);

/// Linear interpolation of (t, y) at `at`; t rising; constant beyond the ends.
double interpolate(const std::vector<double>& t, const std::vector<double>& y, double at);

} // namespace yamsc::analysis
