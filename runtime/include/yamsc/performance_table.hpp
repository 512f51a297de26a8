#pragma once
// A rotor's performance coefficients Cp, Ct, Cq over tip-speed ratio and
// collective pitch, as ROSCO writes them (Cp_Ct_Cq.<turbine>.txt), and their
// C1 interpolation: a tensor product of cubic Hermite interpolants whose node
// slopes are those of the parabola through each node and its neighbours. The
// interpolant passes through every table value, its first derivatives are
// continuous everywhere (outside the table it continues linearly with the
// edge slope), and its partial derivatives are computed exactly, so the
// Jacobians built from them are those of the function being integrated.
#include <istream>
#include <string>
#include <vector>

namespace yamsc::runtime {

struct PerformanceTable {
    std::vector<double> pitch_deg; // columns, increasing [deg]
    std::vector<double> tsr;       // rows, increasing [-]
    // row-major tsr.size() x pitch_deg.size()
    std::vector<double> cp, ct, cq;
};

/// Reads ROSCO's text format (the reader: formats/performance_table): `#` header
/// lines, the pitch vector, the TSR vector, the wind speed vector, then the Cp, Ct
/// and Cq matrices (rows = TSR). Throws std::runtime_error naming `source` and the problem.
PerformanceTable read_performance_table(std::istream& in, const std::string& source);
PerformanceTable read_performance_table(const std::string& path);

/// A coefficient and its partial derivatives per unit TSR and per degree of pitch.
struct Coefficient {
    double value = 0, d_tsr = 0, d_pitch = 0;
};

/// The C1 interpolant of `values` (one of cp, ct, cq of `table`) at (tsr, pitch_deg).
Coefficient interpolate(const PerformanceTable& table, const std::vector<double>& values,
                        double tsr, double pitch_deg);

} // namespace yamsc::runtime
