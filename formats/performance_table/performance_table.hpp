#pragma once
// A rotor's performance coefficients Cp, Ct, Cq over tip-speed ratio and collective
// pitch in ROSCO's text format (Cp_Ct_Cq.<turbine>.txt): `#` header lines, the pitch
// vector, the TSR vector, the wind speed vector, then the Cp, Ct and Cq matrices
// (one row per TSR, one column per pitch angle).
#include <istream>
#include <string>
#include <vector>

namespace yamsc::performance_table {

struct Table {
    std::vector<double> pitch_deg; // columns, increasing, 2 or more [deg]
    std::vector<double> tsr;       // rows, increasing, 2 or more [-]
    // row-major tsr.size() x pitch_deg.size(), finite
    std::vector<double> cp, ct, cq;
};

/// Throws std::runtime_error naming `source` (and the line) and the problem.
Table read_performance_table(std::istream& in, const std::string& source);

} // namespace yamsc::performance_table
