#pragma once
// The hub-height wind speed over time as a text file: a CSV whose first two columns
// are time [s] and speed [m/s] (a header line is skipped), or OpenFAST's uniform wind
// file (InflowWind WindType 2: '!' comments; the direction, shear and gust columns
// after time and speed are not read). '#' lines are comments everywhere.
#include <istream>
#include <string>
#include <vector>

namespace yamsc::wind {

struct Samples {
    std::vector<double> time, speed; // time strictly increasing; one sample or more
};

/// Throws std::runtime_error "source:line: message" (or "source: no wind samples").
Samples read_wind_file(std::istream& in, const std::string& source);

} // namespace yamsc::wind
