#pragma once
// The Campbell diagram of a spinning turbine: its MBC3 modes (rotor_modes.hpp)
// along a swept rotor speed or parameter, `yamsc lin --mbc3 --sweep
// "psi'=0.2:0.1:1.4"`, as a CSV table (one row per mode and value, with its
// label) and an SVG plot with a curve per label and the 1P, 3P and 6P lines.
#include "analysis/loaded_model.hpp"
#include "analysis/rotor_modes.hpp"

#include <iosfwd>

#include <string>
#include <vector>

namespace yamsc::analysis {

struct RotorCampbellRow {
    double value = 0;
    std::vector<RotorMode> modes;
};

/// Header `NAME,mode,label,freq_hz,damping_ratio,share`.
std::string rotor_campbell_csv(const std::string& name, const std::vector<RotorCampbellRow>& rows);

/// Frequency and damping ratio against the swept value, a curve per label (in
/// order of first appearance), and the lines 1P, 3P and 6P of `rotor_speed`
/// [rad/s] at each row (none when it is empty): the swept value itself for a
/// sweep of the rotor speed (`swept_rotor_speed`: the x axis is in rad/s), the
/// scheduled one over wind speed. Rigid-body modes are left out.
std::string rotor_campbell_svg(const std::string& title, const std::string& name,
                               const std::vector<RotorCampbellRow>& rows,
                               const std::vector<double>& rotor_speed, bool swept_rotor_speed);

/// `lin --mbc3 --sweep NAME=FROM:STEP:TO`: NAME is a DOF's rate (`psi'`, the
/// rotor speed in rad/s, which is then the azimuth DOF), an input (`V_wind`,
/// with --aero and a --schedule of rotor speed and controls) or a parameter
/// (analysis/sweep_point.hpp). Writes
/// the CSV (stdout or -o) and the SVG (--plot).
int rotor_campbell(const Loaded& l, const driver::LinOptions& o, std::ostream& out);

} // namespace yamsc::analysis
