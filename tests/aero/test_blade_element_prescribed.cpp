// The deck with every ElastoDyn DOF off, as OpenFAST's rigid-rotor reference
// runs it (data/reference/aero/rigid_U8.csv: 8.9886 rpm, pitch 0, quasi-steady
// BEM), written by from-openfast (a hub and a rigid body per blade, their
// motion prescribed) and simulated with its blade elements: the rotor's
// coefficients, the nodes' angles of attack and the blade-root loads, which
// carry the aerodynamic loads through the blade's mesh into its joint's reaction.
#include "analysis/commands.hpp"
#include "analysis/compare.hpp"
#include "openfast/from_openfast.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>

namespace {

namespace fs = std::filesystem;
const std::string data_dir = YAMSC_TEST_DATA_DIR;

std::string set_entry(std::string text, const std::string& key, const std::string& value) {
    return std::regex_replace(text, std::regex("\n\\s*\\S+(\\s+)" + key + "\\b"),
                              "\n  " + value + "$1" + key);
}

} // namespace

TEST_CASE("every DOF off: the prescribed rigid rotor's blade elements match OpenFAST's") {
    const std::string dir = test_support::scratch_dir("aero", "prescribed_rotor");
    fs::copy(data_dir + "/reference/operating/deck", dir + "/deck", fs::copy_options::recursive);
    const std::string ed = dir + "/deck/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat";
    std::string text = test_support::read_file(ed);
    for (const char* dof : {"FlapDOF1", "FlapDOF2", "EdgeDOF", "TeetDOF", "DrTrDOF", "GenDOF",
                            "YawDOF", "TwFADOF1", "TwFADOF2", "TwSSDOF1", "TwSSDOF2"})
        text = set_entry(text, dof, "False");
    text = set_entry(text, "RotSpeed", "8.9885664");
    test_support::write_file(ed, text);
    const std::string ad = dir + "/deck/NRELOffshrBsline5MW_Onshore_AeroDyn15.dat";
    // The reference's quasi-steady BEM: no dynamic inflow, no unsteady airfoils.
    std::string aero = set_entry(test_support::read_file(ad), "NBlOuts", "9");
    aero = set_entry(aero, "DBEMT_Mod", "0");
    aero = set_entry(aero, "UA_Mod", "0");
    aero = std::regex_replace(aero, std::regex("\n[^\n]*BlOutNd"),
                              "\n3, 5, 7, 9, 11, 13, 15, 17, 18    BlOutNd");
    test_support::write_file(ad, aero);

    yamsc::driver::FromOpenFastOptions o;
    o.deck = dir + "/deck/NREL-5MW.fst";
    o.output = dir + "/rigid.mbd";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    REQUIRE(test_support::read_file(o.output).find("load blade_elements aero") !=
            std::string::npos);

    yamsc::driver::SimOptions s;
    s.model = o.output;
    s.aero = ad;
    s.wind = "8";
    s.tmax = 10;
    s.dt = 0.025;
    s.channels = yamsc::driver::Channels::openfast;
    s.output = dir + "/rigid.csv";
    REQUIRE_MESSAGE(yamsc::analysis::sim(s, out, err) == 0, err.str());
    const yamsc::analysis::Table y = yamsc::analysis::read_table(s.output);
    const yamsc::analysis::Table ref =
        yamsc::analysis::read_table(data_dir + "/reference/aero/rigid_U8.csv");
    auto column = [](const yamsc::analysis::Table& t, const std::string& name) {
        const int c = t.find(name);
        REQUIRE_MESSAGE(c >= 0, name);
        return t.data[static_cast<std::size_t>(c)];
    };
    const auto t_ref = column(ref, "Time_[s]"), t_y = column(y, "Time_[s]");
    int compared = 0;
    for (std::size_t r = 0; r < t_ref.size(); r += 8) {
        // The same instant in yamsc's rows (both every 0.025 s from 0).
        const auto i = static_cast<std::size_t>(std::lround(t_ref[r] / 0.025));
        REQUIRE(i < t_y.size());
        CHECK(t_y[i] == doctest::Approx(t_ref[r]));
        CAPTURE(t_ref[r]);
        auto near = [&](const std::string& name, double rel) {
            CAPTURE(name);
            CHECK(column(y, name)[i] == doctest::Approx(column(ref, name)[r]).epsilon(rel));
        };
        near("Azimuth_[deg]", 1e-6);
        near("RtFldCp_[-]", 0.005);
        near("RtFldCt_[-]", 0.005);
        for (int j = 1; j <= 9; ++j) {
            const std::string alpha = "B1N" + std::to_string(j) + "Alpha_[deg]";
            CHECK(std::abs(column(y, alpha)[i] - column(ref, alpha)[r]) < 0.1);
        }
        // The root bending moments (gravity, the rotation and the air), within
        // 0.1 % of their largest value over the run (RootMzc1: docs/validation.md).
        for (const std::string load :
             {"RootMyc1_[kN-m]", "RootMxc1_[kN-m]", "RootMyb1_[kN-m]", "RootMxb1_[kN-m]"}) {
            CAPTURE(load);
            double largest = 0;
            for (double v : column(ref, load)) largest = std::max(largest, std::abs(v));
            CHECK(std::abs(column(y, load)[i] - column(ref, load)[r]) < 1e-3 * largest);
        }
        ++compared;
    }
    CHECK(compared >= 10);
}
