#pragma once
// What tower influence and tower drag do to the flexible NREL 5-MW turbine at
// 8 m/s, measured on two runs of the same turbine without and with them
// (OpenFAST's flex_U8 and twr_U8, or yamsc's runs of those decks), so that a
// reference test can compare yamsc's effect with OpenFAST's.
#include <string>
#include <vector>

#include "table/table.hpp"
#include "yamsc/aero/rotor_input.hpp"

namespace tower_reference {

// The tower table of the deck's AeroDyn file (TwrElev, TwrDiam, TwrCd, TwrTI).
std::vector<yamsc::aero::TowerNode> five_mw_tower_table();

struct Statistics {
    double mean = 0, deviation = 0; // population standard deviation
};
// A column's statistics over the rows with from <= time < to. Throws on a
// missing column or an empty window.
Statistics statistics(const yamsc::table::Table& run, const std::string& column, double from,
                      double to = 1e300);

// A column's mean per azimuth bin of blade 1 (Azimuth_[deg]; bins of 360/bins
// degrees, bin 0 from 0), rows with time >= from.
std::vector<double> azimuth_profile(const yamsc::table::Table& run, const std::string& column,
                                    double from, int bins);

// The tower's effect: the run with tower influence minus the run without,
// in the CSVs' units (kN, kN m, W, m), over time >= from.
struct Effect {
    double thrust_change = 0;            // RotThrust_[kN]
    double power_change = 0;             // RtFldPwr_[W]
    double tower_base_moment_change = 0; // TwrBsMyt_[kN-m]
    double tower_top_change = 0;         // TTDspFA_[m]
    double root_flap_change = 0;         // RootMyc1_[kN-m]
    double rotor_wind_change = 0;        // RtVAvgxh_[m/s]: the blades' disturbed wind
    double thrust_deviation_without = 0, thrust_deviation_with = 0; // RotThrust_[kN]
    // RootMyc1 of blade 1 as it passes the tower (azimuth 180-210 deg, where
    // it dips most) minus its value there without the tower.
    double root_flap_dip = 0;
};
// The largest difference between a column's change (with - without) over
// [bounds.front(), bounds.back()) and its changes over the windows between
// successive bounds: how well the runs know that change.
double change_spread(const yamsc::table::Table& without, const yamsc::table::Table& with,
                     const std::string& column, const std::vector<double>& bounds);

Effect effect(const yamsc::table::Table& without, const yamsc::table::Table& with, double from);
Effect effect(const std::string& without_csv, const std::string& with_csv, double from);

} // namespace tower_reference
