// The deck with every ElastoDyn DOF off, as OpenFAST's rigid-rotor reference
// runs it (data/reference/aero/rigid_U8.csv: 8.9886 rpm, pitch 0, quasi-steady
// BEM), written by from-openfast (a hub and a rigid body per blade, their
// motion prescribed) and simulated with its blade elements: the rotor's
// coefficients, the nodes' angles of attack and the blade-root loads, which
// carry the aerodynamic loads through the blade's mesh into its joint's reaction.
#include "analysis/commands.hpp"
#include "rigid_deck.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using aero_test::column;

TEST_CASE("every DOF off: the prescribed rigid rotor's blade elements match OpenFAST's") {
    const std::string dir = test_support::scratch_dir("aero", "prescribed_rotor");
    const aero_test::RigidDeck deck = aero_test::rigid_deck(dir);
    REQUIRE(test_support::read_file(deck.model).find("load blade_elements aero") !=
            std::string::npos);

    yamsc::driver::SimOptions s;
    s.model = deck.model;
    s.aero = deck.aerodyn;
    s.wind = "8";
    s.tmax = 10;
    s.dt = 0.025;
    s.channels = yamsc::driver::Channels::openfast;
    s.output = dir + "/rigid.csv";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::analysis::sim(s, out, err) == 0, err.str());
    const yamsc::analysis::Table y = yamsc::analysis::read_table(s.output);
    const yamsc::analysis::Table ref = yamsc::analysis::read_table(
        std::string(YAMSC_TEST_DATA_DIR) + "/reference/aero/rigid_U8.csv");
    const int compared = aero_test::compare_rotor_rows(y, ref, [&](std::size_t i, std::size_t r) {
        // The root bending moments (gravity, the rotation and the air), within
        // 0.1 % of their largest value over the run (RootMzc1: docs/validation.md).
        for (const std::string load :
             {"RootMyc1_[kN-m]", "RootMxc1_[kN-m]", "RootMyb1_[kN-m]", "RootMxb1_[kN-m]"}) {
            CAPTURE(load);
            double largest = 0;
            for (double v : column(ref, load)) largest = std::max(largest, std::abs(v));
            CHECK(std::abs(column(y, load)[i] - column(ref, load)[r]) < 1e-3 * largest);
        }
    });
    CHECK(compared >= 10);
}
