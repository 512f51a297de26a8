// `yamsc lin` linearizes at the model's `linearize` point, evaluated with the
// parameters of the run (--set), overridden by --at.
#include "generated_model.hpp"
#include "json_values.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

using namespace linear_test;
using test_support::json_array;
using test_support::json_number;

namespace {

const std::string model = std::string(YAMSC_SOURCE_DIR) + "/tests/linear/models/pendulum_op.mbd";

struct Lin {
    std::string out, err;
};

Lin lin(const std::string& args) {
    const std::string dir = scratch_dir("lin_command");
    const std::string cmd = std::string(YAMSC_EXE) + " lin " + model + " " + args + " > " + dir +
                            "/out.txt 2> " + dir + "/err.txt";
    REQUIRE(run(cmd));
    return {read_file(dir + "/out.txt"), read_file(dir + "/err.txt")};
}

} // namespace

TEST_CASE("yamsc lin: the model's operating point, a function of the parameters") {
    const double m = 1.3, L = 0.9, g = 9.81, c = 0.2;
    for (double th0 : {0.4, 0.9}) {
        CAPTURE(th0);
        Lin r = lin("--json" + (th0 == 0.4 ? std::string() : " --set th0=0.9"));
        CHECK(json_array(r.out, "q0")[0] == doctest::Approx(th0).epsilon(1e-15));
        CHECK(json_array(r.out, "u0")[0] ==
              doctest::Approx(m * g * L * std::sin(th0)).epsilon(1e-14));
        CHECK(json_number(r.out, "equilibrium_residual") < 1e-12);
        // No warning (stderr may say that the model is being compiled).
        CHECK(r.err.find("warning") == std::string::npos);
        const double wn = std::sqrt(g * std::cos(th0) / L);
        CHECK(json_number(r.out, "freq_hz") == doctest::Approx(wn / (2 * M_PI)).epsilon(1e-12));
        CHECK(json_number(r.out, "damping_ratio") ==
              doctest::Approx(c / (2 * m * L * L * wn)).epsilon(1e-12));
    }
}

TEST_CASE("yamsc lin: --at overrides the point and a moving point is reported") {
    Lin r = lin("--json --at theta=0.7");
    CHECK(json_array(r.out, "q0")[0] == 0.7);
    // The torque still holds 0.4 rad: not an equilibrium at 0.7 rad.
    const double F = 1.3 * 9.81 * 0.9 * (std::sin(0.4) - std::sin(0.7));
    CHECK(json_array(r.out, "residual")[0] == doctest::Approx(F).epsilon(1e-12));
    Lin text = lin("--at theta=0.7,tau=1");
    CHECK(text.err.find("warning: the operating point is not an equilibrium") != std::string::npos);
    Lin inputs = lin("--json --at tau=2.5");
    CHECK(json_array(inputs.out, "u0")[0] == 2.5);
}

TEST_CASE("yamsc lin --sweep: a Campbell diagram as CSV and SVG") {
    const std::string dir = scratch_dir("campbell");
    const std::string blade = std::string(YAMSC_SOURCE_DIR) + "/models/nrel5mw_blade.mbd";
    REQUIRE(run(std::string(YAMSC_EXE) + " lin " + blade + " --sweep Omega=0:0.4:1.2 -o " + dir +
                "/c.csv --plot " + dir + "/c.svg > " + dir + "/out.txt"));
    const std::string csv = read_file(dir + "/c.csv");
    std::istringstream lines(csv);
    std::string header, line;
    std::getline(lines, header);
    CHECK(header == "Omega,mode1_freq_hz,mode1_damping_ratio,mode2_freq_hz,mode2_damping_ratio,"
                    "mode3_freq_hz,mode3_damping_ratio");
    std::vector<std::vector<double>> rows;
    while (std::getline(lines, line)) {
        std::vector<double> row;
        std::istringstream cells(line);
        std::string cell;
        while (std::getline(cells, cell, ',')) row.push_back(std::strtod(cell.c_str(), nullptr));
        rows.push_back(row);
    }
    REQUIRE(rows.size() == 4);
    CHECK(rows[1][0] == 0.4);
    CHECK(rows[3][0] == 1.2);
    // Centrifugal stiffening: the flap frequency rises with the rotor speed, more
    // than the edge frequency (paper section 4.3).
    for (std::size_t k = 1; k < rows.size(); ++k) CHECK(rows[k][1] > rows[k - 1][1]);
    const double flap_rise = rows[3][1] / rows[0][1] - 1, edge_rise = rows[3][3] / rows[0][3] - 1;
    MESSAGE("flap 1: " << rows[0][1] << " -> " << rows[3][1] << " Hz, edge 1: " << rows[0][3]
                       << " -> " << rows[3][3] << " Hz");
    CHECK(flap_rise > 0.05);
    CHECK(edge_rise < flap_rise / 2);
    // The same as a single linearization at that speed.
    const std::string single = dir + "/single.json";
    REQUIRE(run(std::string(YAMSC_EXE) + " lin " + blade + " --set Omega=1.2 --json > " + single));
    CHECK(json_number(read_file(single), "freq_hz") == doctest::Approx(rows[3][1]).epsilon(1e-12));
    const std::string svg = read_file(dir + "/c.svg");
    CHECK(svg.rfind("<svg", 0) == 0);
    std::size_t lines_drawn = 0;
    for (auto p = svg.find("<polyline"); p != std::string::npos; p = svg.find("<polyline", p + 1))
        ++lines_drawn;
    CHECK(lines_drawn == 6); // 3 modes, frequency and damping panels
}

TEST_CASE("yamsc lin --sweep: the operating point follows the swept parameter") {
    const std::string dir = scratch_dir("campbell_point");
    REQUIRE(run(std::string(YAMSC_EXE) + " lin " + model + " --sweep th0=0:0.3:0.9 > " + dir +
                "/c.csv"));
    std::istringstream lines(read_file(dir + "/c.csv"));
    std::string line;
    std::getline(lines, line);
    for (double th0 : {0.0, 0.3, 0.6, 0.9}) {
        REQUIRE(std::getline(lines, line));
        const std::size_t comma = line.find(',');
        REQUIRE(comma != std::string::npos);
        const double f = std::strtod(line.substr(comma + 1).c_str(), nullptr);
        CHECK(f ==
              doctest::Approx(std::sqrt(9.81 * std::cos(th0) / 0.9) / (2 * M_PI)).epsilon(1e-12));
    }
}
