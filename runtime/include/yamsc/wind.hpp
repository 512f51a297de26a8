#pragma once
// The hub-height wind speed as a signal of time: steady, a step, or a table
// (time, speed) interpolated linearly and held constant beyond its ends.
#include <string>
#include <vector>

namespace yamsc::runtime {

struct WindSignal {
    std::vector<double> time, speed; // one point: steady
    /// The speed at time t [m/s].
    double operator()(double t) const;
};

/// "11.4" (steady), "step:8:14:t=10" (8 m/s, 14 m/s from t = 10 s) or the path
/// of a wind file (formats/wind: a CSV whose first two columns are time [s] and
/// speed [m/s], a header line skipped, or OpenFAST's uniform wind file).
/// Throws std::invalid_argument / std::runtime_error.
WindSignal parse_wind(const std::string& spec);

} // namespace yamsc::runtime
