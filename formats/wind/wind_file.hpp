#pragma once
// Wind over time as a text file: a CSV whose first two columns are time [s] and
// speed [m/s] (a header line is skipped; further columns are not read), or
// OpenFAST's uniform wind file (InflowWind WindType 2: '!' comments; whitespace
// separated columns Time, Wind Speed, Wind Dir, Vert Speed, Horiz Shear, Pwr Law
// Vert Shr, Lin Vert Shear, Gust Speed and the optional Upflow, the count of the
// first row read from every row, columns left out zero). '#' lines are comments
// everywhere.
#include <istream>
#include <string>
#include <vector>

namespace yamsc::wind {

/// The columns of a uniform wind file, in its units (angles in degrees).
struct Samples {
    std::vector<double> time, speed; // time strictly increasing; one sample or more
    // The same length as time, zero where the file has no such column.
    std::vector<double> direction, vertical, horizontal_shear, power_law, linear_vertical_shear,
        gust, upflow;
    int columns = 2; // how many of the columns above the file gives (2 to 9)
};

/// The most columns a uniform wind file has (InflowWind's MaxNumCols).
inline constexpr int max_columns = 9;

/// Throws std::runtime_error "source:line:col: message" (or "source: no wind samples").
Samples read_wind_file(std::istream& in, const std::string& source);

} // namespace yamsc::wind
