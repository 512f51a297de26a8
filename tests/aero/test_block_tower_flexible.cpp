// The tower inside `load blade_elements` on the flexible NREL 5-MW turbine at
// fixed speed in 8 m/s (OpenFAST's flex_U8 and twr_U8: GenDOF, DrTrDOF and
// YawDOF off, 8.9886 rpm, pitch 0): what the tower's potential flow and drag
// change, yamsc with minus yamsc without against OpenFAST's twr minus flex.
// The effects are compared, not the runs: OpenFAST's runs have dynamic inflow
// and unsteady airfoils, which the block's steady BEM here leaves out, and
// which move both runs alike.
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "analysis/sim_case.hpp"
#include "openfast/from_openfast.hpp"
#include "test_files.hpp"
#include "tower_reference.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

namespace {

namespace fs = std::filesystem;
const std::string data_dir = YAMSC_TEST_DATA_DIR;
const std::string aerodyn_file = "/NRELOffshrBsline5MW_Onshore_AeroDyn15.dat";

/// The deck with TwrPotent 1 and TwrAero True (twr_U8's changes).
std::string tower_deck() {
    const std::string d = test_support::scratch_dir("aero", "block_tower_flexible_deck");
    fs::remove_all(d);
    fs::copy(data_dir + "/reference/operating/deck", d, fs::copy_options::recursive);
    std::istringstream in(test_support::read_file(d + aerodyn_file));
    std::string text, line;
    while (std::getline(in, line)) {
        if (line.find("TwrPotent") != std::string::npos) line = "1   TwrPotent";
        if (line.find("TwrAero") != std::string::npos) line = "True   TwrAero";
        text += line + "\n";
    }
    test_support::write_file(d + aerodyn_file, text);
    return d;
}

} // namespace

TEST_CASE("the blade-element block's tower on the flexible turbine: OpenFAST's twr_U8 - flex_U8") {
    const std::string deck = tower_deck();
    const std::string dir = test_support::scratch_dir("aero", "block_tower_flexible");
    yamsc::driver::FromOpenFastOptions o;
    o.deck = deck + "/NREL-5MW.fst";
    o.output = dir + "/fixed_speed.mbd";
    o.dofs = {{"GenDOF", false}, {"DrTrDOF", false}, {"YawDOF", false}};
    {
        std::ostringstream out, err;
        REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    }

    // Both runs start from flex_U8's mean deflections (its last 20 s), so
    // that the few seconds simulated are about the tower's effect, not the
    // start from rest.
    const std::string ref = data_dir + "/reference/aero/";
    const yamsc::table::Table flex = yamsc::table::read_table(ref + "flex_U8.csv");
    auto mean = [&](const char* column) {
        return tower_reference::statistics(flex, column, 60.0).mean;
    };
    yamsc::driver::SimOptions s;
    s.model = o.output;
    s.set = {{"Omega0", 0, 0.941288}};
    s.tmax = 30;
    s.dt = 0.00625;
    s.dt_out = 0.1;
    s.u = {{"V_wind", 0, 8.0}};
    s.ic = {{"q_fa1", 0, mean("Q_TFA1_[m]")}, {"q_ss1", 0, mean("Q_TSS1_[m]")}};
    for (int k = 1; k <= 3; ++k) {
        const std::string b = "q_b" + std::to_string(k) + "_";
        s.ic.push_back({b + "flap1", 0, mean("Q_B1F1_[m]")});
        s.ic.push_back({b + "edge1", 0, mean("Q_B1E1_[m]")});
        s.ic.push_back({b + "flap2", 0, mean("Q_B1F2_[m]")});
    }
    std::ostringstream err;
    auto l = yamsc::analysis::load(o.output, s.set, "", false, err, {},
                                   yamsc::analysis::sim_routines(s));
    REQUIRE_MESSAGE(l, err.str());
    std::string csv[2];
    for (int with = 0; with < 2; ++with) {
        s.aero = (with ? deck : data_dir + "/reference/operating/deck") + aerodyn_file;
        std::ostringstream out;
        const yamsc::analysis::SimRun run = yamsc::analysis::simulate_case(*l, s, out, err);
        REQUIRE(run.result.completed);
        csv[with] = dir + (with ? "/twr.csv" : "/flex.csv");
        yamsc::analysis::write_sim_csv(run, yamsc::driver::Channels::openfast, csv[with]);
    }
    const double from = 15;
    const tower_reference::Effect mine = tower_reference::effect(csv[0], csv[1], from);
    const tower_reference::Effect theirs =
        tower_reference::effect(ref + "flex_U8.csv", ref + "twr_U8.csv", 60.0);
    MESSAGE("TwrBsMyt change " << mine.tower_base_moment_change << " (OpenFAST "
                               << theirs.tower_base_moment_change << ") kN m");
    MESSAGE("TTDspFA change " << mine.tower_top_change << " (" << theirs.tower_top_change << ") m");
    MESSAGE("RotThrust change " << mine.thrust_change << " (" << theirs.thrust_change << ") kN");
    MESSAGE("RotThrust std " << mine.thrust_deviation_without << " -> "
                             << mine.thrust_deviation_with << " ("
                             << theirs.thrust_deviation_without << " -> "
                             << theirs.thrust_deviation_with << ") kN");
    MESSAGE("RootMyc1 dip 180-210 deg " << mine.root_flap_dip << " (" << theirs.root_flap_dip
                                        << ") kN m");
    MESSAGE("RtVAvgxh change " << mine.rotor_wind_change << " (" << theirs.rotor_wind_change
                               << ") m/s");
    MESSAGE("power change " << mine.power_change << " (" << theirs.power_change << ") W");
}
