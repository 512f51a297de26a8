// The deck with every ElastoDyn DOF off, as OpenFAST's rigid-rotor reference
// runs it (the rigid runs of data/reference/aero/cases.txt: fixed rotor speed
// and pitch, quasi-steady BEM), written by from-openfast (a hub and a rigid body
// per blade, their motion prescribed) and simulated with its blade elements over
// the run's rows (from its first row's azimuth: nothing else carries over a
// prescribed quasi-steady rotor's past): the rotor's coefficients, the nodes'
// angles of attack and the blade-root loads, which carry the aerodynamic loads
// through the blade's mesh into its joint's reaction.
#include "analysis/commands.hpp"
#include "analysis/compare.hpp"
#include "openfast/from_openfast.hpp"
#include "reference_cases.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace {

std::string number(double x) {
    std::ostringstream s;
    s << std::setprecision(10) << x;
    return s.str();
}

/// The run simulated over its rows; they and the reference compared.
void compare(const reference_cases::Case& c) {
    CAPTURE(c.file);
    const yamsc::analysis::Table ref = yamsc::analysis::read_table(c.path());
    auto column = [](const yamsc::analysis::Table& t, const std::string& name) {
        const int i = t.find(name);
        REQUIRE_MESSAGE(i >= 0, name);
        return t.data[static_cast<std::size_t>(i)];
    };
    const auto t_ref = column(ref, "Time_[s]");
    const double t0 = t_ref.front();

    reference_cases::Settings settings = c.settings;
    for (const char* dof : {"FlapDOF1", "FlapDOF2", "EdgeDOF", "TeetDOF", "DrTrDOF", "GenDOF",
                            "YawDOF", "TwFADOF1", "TwFADOF2", "TwSSDOF1", "TwSSDOF2"})
        settings.emplace_back(dof, "False");
    settings.emplace_back("RotSpeed", number(c.rpm));
    settings.emplace_back("HWindSpeed", number(c.wind));
    settings.emplace_back("Azimuth", number(column(ref, "Azimuth_[deg]").front()));
    for (const char* b : {"BlPitch(1)", "BlPitch(2)", "BlPitch(3)"})
        settings.emplace_back(b, number(c.pitch_deg));
    const std::string dir = test_support::scratch_dir("aero", "prescribed_" + c.name());
    const std::string deck = reference_cases::deck("prescribed_" + c.name() + "_deck", settings);

    yamsc::driver::FromOpenFastOptions o;
    o.deck = deck + "/NREL-5MW.fst";
    o.output = dir + "/rigid.mbd";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    REQUIRE(test_support::read_file(o.output).find("load blade_elements aero") !=
            std::string::npos);

    yamsc::driver::SimOptions s;
    s.model = o.output;
    s.aero = deck + reference_cases::aerodyn_file;
    s.wind = deck + "/NRELOffshrBsline5MW_InflowWind.dat"; // its direction too
    s.u = {{"pitch", 0, c.pitch_deg * M_PI / 180}};
    s.tmax = t_ref.back() - t0;
    s.dt = 0.025;
    s.channels = yamsc::driver::Channels::openfast;
    s.output = dir + "/rigid.csv";
    REQUIRE_MESSAGE(yamsc::analysis::sim(s, out, err) == 0, err.str());
    const yamsc::analysis::Table y = yamsc::analysis::read_table(s.output);
    const auto t_y = column(y, "Time_[s]");
    int compared = 0;
    for (std::size_t r = 0; r < t_ref.size(); r += 8) {
        // The same instant in yamsc's rows (both every 0.025 s, yamsc's from the first).
        const auto i = static_cast<std::size_t>(std::lround((t_ref[r] - t0) / 0.025));
        REQUIRE(i < t_y.size());
        CHECK(t_y[i] + t0 == doctest::Approx(t_ref[r]));
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

} // namespace

TEST_CASE("every DOF off: the prescribed rigid rotor's blade elements match OpenFAST's") {
    for (const reference_cases::Case& c : reference_cases::cases(reference_cases::Kind::rigid))
        compare(c);
}
