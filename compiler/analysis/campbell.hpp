#pragma once
// Campbell diagrams: the modes of the linear model along a swept parameter
// (`yamsc lin MODEL --sweep Omega=0:0.1:1.3 [-o campbell.csv] [--plot campbell.svg]`),
// as a CSV table and an SVG plot of the frequencies and damping ratios.
#include "driver/values.hpp"

#include <yamsc/modal.hpp>

#include <string>
#include <vector>

namespace yamsc::analysis {

/// The modes at one value of the swept parameter, sorted by frequency.
struct CampbellRow {
    double value = 0;
    std::vector<runtime::Mode> modes;
};

/// Header `NAME,mode1_freq_hz,mode1_damping_ratio,...`, one row per value; the
/// k-th column pair is the k-th mode by frequency at that value (rigid-body
/// modes first, frequency 0, damping empty).
std::string campbell_csv(const std::string& name, const std::vector<CampbellRow>& rows);

/// Two stacked panels (frequency [Hz], damping ratio) against the parameter, one
/// line per mode index; deterministic text.
std::string campbell_svg(const std::string& title, const std::string& name,
                         const std::vector<CampbellRow>& rows);

} // namespace yamsc::analysis
