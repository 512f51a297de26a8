#pragma once
// The wind a command runs in (`--wind SPEC`): the hub-height wind speed as a
// signal of time (steady, a step, or a table (time, speed) interpolated linearly
// and held constant beyond its ends) and, from an InflowWind input file, the
// wind field around the turbine (yamsc/wind/wind_field.hpp).
#include "yamsc/wind/wind_field.hpp"

#include <memory>
#include <string>
#include <vector>

namespace yamsc::runtime {

struct WindSignal {
    std::vector<double> time, speed; // one point: steady
    /// > 0: the samples repeat with this period from time.front() (a periodic
    /// full field), else held constant beyond the ends.
    double period = 0;
    /// The speed at time t [m/s].
    double operator()(double t) const;
};

/// What --wind names.
struct WindInput {
    /// V_wind over time: the model's wind input (for a field, its reference speed).
    WindSignal hub;
    /// The field at every point; null: the wind is V_wind along ground x everywhere.
    std::shared_ptr<const WindField> field;
    /// "file:line:col: warning: ..." for entries of the file that are not used.
    std::vector<std::string> warnings;
    /// The files read: the spec's, then those it names (a uniform wind file).
    std::vector<std::string> files;
};

/// "11.4" (steady), "step:8:14:t=10" (8 m/s, 14 m/s from t = 10 s), the path of
/// a wind file (formats/wind: a CSV whose first two columns are time [s] and
/// speed [m/s], a header line skipped, or OpenFAST's uniform wind file, of which
/// only time and speed are read: its direction, shear and gust need the
/// reference height and length of an InflowWind file), or the path of an
/// InflowWind input file (WindType 1, 2, 3 or 5: src/wind/wind_kinds.cpp).
/// Throws std::invalid_argument (a malformed spec) / std::runtime_error (a file:
/// "file:line:col: message").
WindInput open_wind(const std::string& spec);

/// open_wind(spec).hub.
WindSignal parse_wind(const std::string& spec);

} // namespace yamsc::runtime
