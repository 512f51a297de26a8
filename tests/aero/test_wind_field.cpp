// InflowWind's uniform wind field (yamsc/wind/uniform_field.hpp) at hand-computed
// points: the values below are InflowWind's formulas (UniformField_GetVel,
// UniformField_InterpLinear, InflowWind_SetParameters' RotToWind) evaluated
// outside yamsc; and the InflowWind file's reader: located errors and warnings.
#include "test_files.hpp"

#include <yamsc/wind.hpp>
#include <yamsc/wind/uniform_field.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace {

using Eigen::Vector3d;
using yamsc::runtime::UniformField;
using yamsc::runtime::UniformWindSetup;

constexpr double deg = 3.14159265358979323846 / 180;

void check_near(const Vector3d& v, const Vector3d& expected) {
    CAPTURE(v.transpose());
    CAPTURE(expected.transpose());
    CHECK((v - expected).norm() < 1e-12 * (1 + expected.norm()));
}

/// An InflowWind file like the deck's, with the given first-section and
/// WindType 1 and 2 entries.
std::string inflowwind_text(const std::string& wind_type, const std::string& prop,
                            const std::string& upflow, const std::string& steady,
                            const std::string& uniform_file) {
    return "------- InflowWind v3.01.* INPUT FILE ------\n"
           "test wind\n"
           "-------------------------------------------\n"
           "False         Echo           - Echo input data\n" +
           wind_type + "   WindType       - switch for wind file type\n" + prop +
           "   PropagationDir - Direction of wind propagation (deg)\n" + upflow +
           "   VFlowAng       - Upflow angle (deg)\n"
           "False         VelInterpCubic - cubic interpolation\n"
           "          1   NWindVel       - Number of points\n"
           "          0   WindVxiList    - X (m)\n"
           "          0   WindVyiList    - Y (m)\n"
           "         90   WindVziList    - Z (m)\n"
           "================== Parameters for Steady Wind Conditions ========\n" +
           steady +
           "================== Parameters for Uniform wind file ==============\n"
           "\"" +
           uniform_file +
           "\"      FileName_Uni   - Filename\n"
           "         90   RefHt_Uni      - Reference height (m)\n"
           "        126   RefLength      - Reference length (m)\n"
           "================== Parameters for Binary TurbSim Full-Field files ====\n"
           "\"unused.bts\"    FileName_BTS   - Name of the Full field wind file\n"
           "====================== OUTPUT ==================================================\n"
           "False         SumPrint     - Print summary data\n"
           "              OutList      - The next line(s) contains a list of output parameters.\n"
           "\"Wind1VelX\"               X-direction wind velocity at point WindList(1)\n"
           "END of input file\n";
}

const std::string steady_section = "         8.0   HWindSpeed     - Horizontal windspeed (m/s)\n"
                                   "         90   RefHt          - Reference height (m)\n"
                                   "        0.2   PLexp          - Power law exponent (-)\n";

/// A file in the test's folder (emptied once per run).
std::string write(const std::string& name, const std::string& text) {
    static const std::string dir = test_support::scratch_dir("aero", "wind_field");
    const std::string path = dir + "/" + name;
    test_support::write_file(path, text);
    return path;
}

std::string error_of(const std::string& spec) {
    try {
        yamsc::runtime::open_wind(spec);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("wind field: steady power law, propagation direction and upflow (WindType 1)") {
    UniformWindSetup s;
    s.samples = yamsc::runtime::steady_wind(8.0, 0.2);
    s.reference_height = 90;
    s.propagation_dir = 20 * deg;
    s.vertical_flow_angle = 5 * deg;
    const UniformField f(s);
    CHECK(f.steady());
    CHECK(f.reference_speed(123.0) == 8.0);
    // Turned about [0 0 RefHt] into the wind's axes, the power law there, turned back.
    check_near(f.velocity(0, Vector3d(3, -20, 150), 8.0),
               Vector3d(8.282622167396992, -3.0146279306059234, 0.771141038981139));
    s.vertical_flow_angle = 0;
    const UniformField level(s);
    check_near(level.velocity(7, Vector3d(-5, 40, 30), 8.0),
               Vector3d(6.034642575873955, -2.196430272053642, 0.0));
    // PropagationDir is meteorological: 20 deg turns +X towards -Y.
    check_near(level.velocity(0, Vector3d(0, 0, 90), 8.0),
               8.0 * Vector3d(std::cos(20 * deg), -std::sin(20 * deg), 0));
    // At and below the ground, no wind.
    check_near(level.velocity(0, Vector3d(0, 0, -1), 8.0), Vector3d::Zero());
    check_near(level.velocity(0, Vector3d(0, 0, 0), 8.0), Vector3d::Zero());
    // Another V_wind scales the whole profile (InflowWind's linearized HWindSpeed).
    check_near(level.velocity(0, Vector3d(-5, 40, 30), 10.0),
               10.0 / 8.0 * Vector3d(6.034642575873955, -2.196430272053642, 0.0));
}

TEST_CASE("wind field: a uniform wind file's nine columns, linear in time (WindType 2)") {
    // Time, speed, direction, vertical speed, horizontal shear, power law, linear
    // vertical shear, gust, upflow.
    const std::string file = write("columns.wnd", "! a uniform wind file\n"
                                                  "10  8  10 0.5 0.1 0.1 0.05 1.0 2\n"
                                                  "20 12  30 1.5 0.3 0.3 0.15 3.0 6\n");
    const std::string dat =
        write("uniform.dat", inflowwind_text("2", "0", "0", steady_section, "columns.wnd"));
    const yamsc::runtime::WindInput w = yamsc::runtime::open_wind(dat);
    REQUIRE(w.field);
    CHECK_FALSE(w.field->steady());
    // The files read: the InflowWind file, then the uniform wind file it names.
    REQUIRE(w.files.size() == 2);
    CHECK(w.files[0] == dat);
    CHECK(w.files[1] == file);
    // V_wind is the speed with the gust, at the reference height.
    CHECK(w.hub(15.0) == doctest::Approx(12.0));
    CHECK(w.field->reference_speed(15.0) == doctest::Approx(12.0));
    CHECK(w.hub(0.0) == doctest::Approx(9.0));
    const Vector3d p(10, 20, 120);
    check_near(w.field->velocity(15.0, p, 12.0),
               Vector3d(12.292183288269934, -4.473988831074705, 1.9171592962609396));
    // V_wind 22 m/s at t = 15 s: the speed column replaced by 22 - gust.
    check_near(w.field->velocity(15.0, p, 22.0),
               Vector3d(22.775109066588346, -8.2894617824044694, 2.6972415947738044));
    // Held beyond the last row.
    check_near(w.field->velocity(100.0, p, 15.0),
               Vector3d(14.633430004652071, -8.448614752353418, 3.2842328045461118));
    // The file's warnings: the OutList and the output point.
    REQUIRE(w.warnings.size() == 2);
    CHECK(w.warnings[0].find("uniform.dat:9:") != std::string::npos);
    CHECK(w.warnings[0].find("NWindVel") != std::string::npos);
    CHECK(w.warnings[1].find("OutList") != std::string::npos);

    // With PropagationDir 15 deg on top of the file's direction.
    const UniformField* u = dynamic_cast<const UniformField*>(w.field.get());
    REQUIRE(u);
    UniformWindSetup s = u->setup();
    s.propagation_dir = 15 * deg;
    check_near(UniformField(s).velocity(15.0, p, 12.0),
               Vector3d(10.714148337722092, -7.502127431570039, 1.9170538326666053));
}

TEST_CASE("wind field: the direction never jumps by half a turn between rows") {
    UniformWindSetup s;
    s.reference_height = 90;
    s.samples.time = {0, 10};
    s.samples.speed = {8, 8};
    s.samples.direction = {350 * deg, 10 * deg};
    s.samples.vertical = s.samples.horizontal_shear = s.samples.power_law =
        s.samples.linear_vertical_shear = s.samples.gust = s.samples.upflow = {0, 0};
    const UniformField f(s);
    // Half way, through north (0 deg), not through south.
    check_near(f.velocity(5.0, Vector3d(0, 0, 90), 8.0), Vector3d(8, 0, 0));
}

TEST_CASE("wind field: the InflowWind file's errors are located") {
    const std::string bladed =
        write("bladed.dat", inflowwind_text("4", "0", "0", steady_section, "none.wnd"));
    CHECK(error_of(bladed).find("bladed.dat:5:1: WindType 4 is not supported; supported: 1 "
                                "(steady), 2 (uniform wind file), 3 (TurbSim full field), 5 "
                                "(HAWC full field)") != std::string::npos);
    const std::string tbs =
        write("turbsim.dat", inflowwind_text("3", "0", "0", steady_section, "none.wnd"));
    CHECK(error_of(tbs).find("turbsim.dat:22:1: FileName_BTS: cannot read") != std::string::npos);
    const std::string bad =
        write("bad.dat", inflowwind_text("1", "x20", "0", steady_section, "none.wnd"));
    CHECK(error_of(bad).find("bad.dat:6:1: PropagationDir: expected a number") !=
          std::string::npos);
    const std::string negative =
        write("negative.dat", inflowwind_text("1", "0", "0",
                                              "  -8.0   HWindSpeed  - speed\n"
                                              "  90     RefHt       - height\n"
                                              "  0.2    PLexp       - exponent\n",
                                              "none.wnd"));
    CHECK(error_of(negative).find("negative.dat:14:3: HWindSpeed: the horizontal wind speed "
                                  "must be positive") != std::string::npos);
    const std::string missing =
        write("missing.dat", inflowwind_text("2", "0", "0", steady_section, "none.wnd"));
    CHECK(error_of(missing).find("missing.dat:18:1: cannot read the uniform wind file") !=
          std::string::npos);
    // A uniform wind file's row shorter than its first.
    write("short.wnd", "0 8 0 0 0 0 0 0\n10 8 0 0 0\n");
    const std::string short_rows =
        write("short.dat", inflowwind_text("2", "0", "0", steady_section, "short.wnd"));
    CHECK(error_of(short_rows).find("short.wnd:2:11: expected 8 numbers") != std::string::npos);
    // A wind file with a direction, named without an InflowWind file.
    const std::string turned = write("turned.wnd", "0 8 20 0 0 0 0 0\n");
    CHECK(error_of(turned).find("name it in an InflowWind file") != std::string::npos);
    // An entry InflowWind does not know warns at its line.
    const std::string unknown =
        write("unknown.dat",
              inflowwind_text("1", "0", "0", steady_section + "  3  Extra  - ?\n", "none.wnd"));
    const yamsc::runtime::WindInput w = yamsc::runtime::open_wind(unknown);
    REQUIRE_FALSE(w.warnings.empty());
    CHECK(w.warnings[0].find("unknown.dat:17:3: warning: InflowWind: unknown entry 'Extra'") !=
          std::string::npos);
}

TEST_CASE("wind field: the deck's InflowWind file is steady 8 m/s without shear") {
    const yamsc::runtime::WindInput w =
        yamsc::runtime::open_wind(std::string(YAMSC_TEST_DATA_DIR) +
                                  "/reference/operating/deck/NRELOffshrBsline5MW_InflowWind.dat");
    REQUIRE(w.field);
    CHECK(w.hub(50.0) == 8.0);
    check_near(w.field->velocity(0, Vector3d(1, 2, 40), 8.0), Vector3d(8, 0, 0));
}
