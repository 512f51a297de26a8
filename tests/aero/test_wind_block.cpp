// The blade elements in InflowWind's wind (`--wind InflowWind.dat`): the deck
// with every ElastoDyn DOF off (a rigid rotor at 8.9886 rpm, pitch 0, as
// test_blade_element_prescribed.cpp runs it) with the wind propagating at 20 deg
// against OpenFAST's run (data/reference/aero/rigid_U8_prop20.csv); then in
// sheared (PLexp 0.2) yawed wind against the rigid rotor of bem_rotor.hpp fed
// the same field at every node: RtFldCp and RtFldCt within 0.5 %, the nodes'
// angle of attack within 0.1 deg, their Fx and Fy within 1 % of the largest.
#include "aerodyn_input/rotor.hpp"
#include "analysis/commands.hpp"
#include "rigid_deck.hpp"

#include <yamsc/aero/rigid_rotor.hpp>
#include <yamsc/wind.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace {

using aero_test::column;
using yamsc::analysis::Table;
constexpr double pi = 3.14159265358979323846;
constexpr double rpm = 8.9885664;
constexpr int output_nodes[9] = {3, 5, 7, 9, 11, 13, 15, 17, 18};

const std::string& work_dir() {
    static const std::string dir = test_support::scratch_dir("aero", "wind_block");
    return dir;
}

const aero_test::RigidDeck& deck() {
    static const aero_test::RigidDeck d = aero_test::rigid_deck(work_dir());
    return d;
}

/// The run in the deck's InflowWind file with PropagationDir and PLexp set.
/// Each run once per test executable.
Table run_in(const std::string& name, const std::string& propagation, const std::string& plexp) {
    static std::map<std::string, Table> runs;
    if (const auto it = runs.find(name); it != runs.end()) return it->second;
    std::string wind = test_support::read_file(deck().inflowwind);
    wind = aero_test::set_entry(wind, "PropagationDir", propagation);
    wind = aero_test::set_entry(wind, "PLexp", plexp);
    const std::string path = work_dir() + "/" + name + "_InflowWind.dat";
    test_support::write_file(path, wind);
    yamsc::driver::SimOptions s;
    s.model = deck().model;
    s.aero = deck().aerodyn;
    s.tmax = 10;
    s.dt = 0.025;
    s.channels = yamsc::driver::Channels::openfast;
    s.wind = path;
    s.output = work_dir() + "/" + name + ".csv";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::analysis::sim(s, out, err) == 0, err.str());
    return runs[name] = yamsc::analysis::read_table(s.output);
}

double largest(const Table& t, const std::string& what) {
    double m = 0;
    for (int j = 1; j <= 9; ++j)
        for (double v : column(t, "B1N" + std::to_string(j) + what)) m = std::max(m, std::abs(v));
    return m;
}

} // namespace

TEST_CASE("wind: the rigid rotor's blade elements in wind from 20 deg match OpenFAST's") {
    const Table y = run_in("prop20", "20", "0");
    const Table ref = yamsc::analysis::read_table(std::string(YAMSC_TEST_DATA_DIR) +
                                                  "/reference/aero/rigid_U8_prop20.csv");
    const double fx_max = largest(ref, "Fx_[N/m]"), fy_max = largest(ref, "Fy_[N/m]");
    const int compared = aero_test::compare_rotor_rows(y, ref, [&](std::size_t i, std::size_t r) {
        for (int j = 1; j <= 9; ++j)
            for (const auto& [what, largest] :
                 {std::pair<std::string, double>{"Fx_[N/m]", fx_max}, {"Fy_[N/m]", fy_max}}) {
                const std::string n = "B1N" + std::to_string(j) + what;
                CAPTURE(n);
                CHECK(std::abs(column(y, n)[i] - column(ref, n)[r]) < 0.01 * largest);
            }
    });
    CHECK(compared >= 10);
}

TEST_CASE("wind: in sheared, yawed wind the blade elements see the field at each node") {
    const Table y = run_in("shear", "20", "0.2");
    yamsc::diag::Diagnostics diags;
    const auto rotor = yamsc::aerodyn_input::read_aerodyn_rotor(deck().aerodyn, 3, diags);
    REQUIRE_MESSAGE(rotor, diags.render());
    const yamsc::runtime::WindInput wind =
        yamsc::runtime::open_wind(work_dir() + "/shear_InflowWind.dat");
    REQUIRE(wind.field);
    yamsc::aero::RigidRotor rigid(*rotor, yamsc::aero::RotorGeometry{});
    const auto azimuth = column(y, "Azimuth_[deg]");
    const double fx_max = largest(y, "Fx_[N/m]"), fy_max = largest(y, "Fy_[N/m]");
    for (std::size_t i = 0; i < azimuth.size(); i += 20) {
        CAPTURE(azimuth[i]);
        yamsc::aero::OperatingPoint op;
        op.azimuth = azimuth[i] * pi / 180;
        op.rotor_speed = rpm * pi / 30;
        op.wind_speed = 8.0;
        op.wind_field = wind.field.get();
        const yamsc::aero::RotorResult& res = rigid.evaluate(op);
        CHECK(column(y, "RtFldCp_[-]")[i] == doctest::Approx(res.cp).epsilon(0.005));
        CHECK(column(y, "RtFldCt_[-]")[i] == doctest::Approx(res.ct).epsilon(0.005));
        for (int j = 1; j <= 9; ++j) {
            const std::string n = "B1N" + std::to_string(j);
            const auto& bem = res.blades[0][static_cast<std::size_t>(output_nodes[j - 1] - 1)].bem;
            CAPTURE(n);
            CHECK(std::abs(column(y, n + "Alpha_[deg]")[i] - bem.alpha * 180 / pi) < 0.1);
            CHECK(std::abs(column(y, n + "Fx_[N/m]")[i] - bem.fx) < 0.01 * fx_max);
            CHECK(std::abs(column(y, n + "Fy_[N/m]")[i] - bem.fy) < 0.01 * fy_max);
        }
    }
    // The shear is felt: against the same yawed wind without shear, the tip's
    // angle of attack is highest with the blade up (151 m: 11 % more wind) and
    // lowest with it down (29 m: 20 % less).
    const Table unsheared = run_in("prop20", "20", "0");
    const auto sheared_tip = column(y, "B1N9Alpha_[deg]");
    const auto plain_tip = column(unsheared, "B1N9Alpha_[deg]");
    std::size_t up = 0, down = 0;
    for (std::size_t i = 0; i < azimuth.size(); ++i) {
        const double d = sheared_tip[i] - plain_tip[i];
        if (d > sheared_tip[up] - plain_tip[up]) up = i;
        if (d < sheared_tip[down] - plain_tip[down]) down = i;
    }
    MESSAGE("tip alpha, sheared less unsheared: "
            << sheared_tip[up] - plain_tip[up] << " deg at " << azimuth[up] << " deg, "
            << sheared_tip[down] - plain_tip[down] << " deg at " << azimuth[down] << " deg");
    CHECK(sheared_tip[up] - plain_tip[up] > 0.5);
    CHECK(sheared_tip[down] - plain_tip[down] < -0.5);
    CHECK(std::min(azimuth[up], 360 - azimuth[up]) < 20);
    CHECK(std::abs(azimuth[down] - 180) < 20);
}
