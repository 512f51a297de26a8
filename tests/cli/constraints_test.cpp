// Models with constraints through the commands (docs/constraints.md): a pendulum
// written in Cartesian coordinates against the angle pendulum, the rod's
// tension from its lambda, lin's frequency in the independent coordinate, trim,
// a prescribed angle's holding torque, the options lin refuses and a located
// error for a redundant row.
#include "json_values.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using test_support::exit_status;
using test_support::json_number;
using test_support::read_file;
using test_support::scratch_dir;
using test_support::write_file;

namespace {

const std::string yamsc = YAMSC_EXE;

const char* const pendulum_model = R"(model cartesian_pendulum "A point mass on a rod, in x and z"
param m = 1.3, L = 0.8, g = 9.81
dof x, z
gravity (0, 0, -g)
rigid bob { mass = m; com = (0, 0, 0) }
joint ground -> bob { translate x x; translate z z }
constraint relation rod { value = x^2 + z^2 - L^2 }
initial {
    x = L * sin(1.0)
    z = -L * cos(1.0)
}
)";

const char* const driven_model = R"(model driven "A pendulum at a prescribed angle"
param m = 0.7, L = 1.1, g = 9.81, A = 0.4, w = 2.3
dof th
gravity (0, 0, -g)
rigid bob { mass = m; com = (0, 0, -L) }
joint ground -> bob { rotate y th }
constraint prescribed drive { coordinate = th; value = A * sin(w * t) }
)";

/// The columns and the last row of a CSV.
struct LastRow {
    std::vector<std::string> columns;
    std::vector<double> values;
    double at(const std::string& name) const {
        for (std::size_t i = 0; i < columns.size(); ++i)
            if (columns[i] == name) return values.at(i);
        FAIL("no column " << name);
        return 0;
    }
};

LastRow last_row(const std::string& path) {
    std::istringstream in(read_file(path));
    LastRow r;
    std::string line, last, cell;
    std::getline(in, line);
    std::istringstream header(line);
    while (std::getline(header, cell, ',')) r.columns.push_back(cell);
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    std::istringstream row(last);
    while (std::getline(row, cell, ',')) r.values.push_back(std::stod(cell));
    return r;
}

} // namespace

TEST_CASE("constraints: sim of the Cartesian pendulum, its tension, -v's choice and drift") {
    const std::string dir = scratch_dir("cli", "constraints_pendulum");
    const std::string model = dir + "/pendulum.mbd", csv = dir + "/run.csv", log = dir + "/log.txt";
    write_file(model, pendulum_model);
    REQUIRE(exit_status(yamsc + " sim " + model + " --tmax 2 --dt 5e-4 --dt-out 0.5 -v -o " + csv +
                        " > " + log + " 2>&1") == 0);
    const std::string text = read_file(log);
    CHECK(text.find("dependent coordinates: z\n") != std::string::npos);
    CHECK(text.find("max |phi| = ") != std::string::npos);
    const LastRow r = last_row(csv);
    // The angle pendulum from 1 rad at rest, RK4 with a step 8 times smaller.
    const double m = 1.3, L = 0.8, g = 9.81;
    double th = 1.0, w = 0.0;
    const auto f = [&](double a, double b, double& da, double& db) {
        da = b;
        db = -g / L * std::sin(a);
    };
    const double h = 5e-4 / 8;
    for (int k = 0; k < 4 * 8 * 1000; ++k) {
        double k1a, k1b, k2a, k2b, k3a, k3b, k4a, k4b;
        f(th, w, k1a, k1b);
        f(th + h / 2 * k1a, w + h / 2 * k1b, k2a, k2b);
        f(th + h / 2 * k2a, w + h / 2 * k2b, k3a, k3b);
        f(th + h * k3a, w + h * k3b, k4a, k4b);
        th += h / 6 * (k1a + 2 * k2a + 2 * k3a + k4a);
        w += h / 6 * (k1b + 2 * k2b + 2 * k3b + k4b);
    }
    REQUIRE(r.at("time") == 2.0);
    // The CSV's 10 significant digits bound the comparison.
    CHECK(std::atan2(r.at("x"), -r.at("z")) == doctest::Approx(th).epsilon(1e-9));
    const double tension = m * (g * std::cos(th) + L * w * w);
    CHECK(-2 * L * r.at("lambda:rod") == doctest::Approx(tension).epsilon(1e-9));
    CHECK(std::fabs(r.at("phi:rod")) < 1e-10);
    CHECK(std::fabs(r.at("constraint_velocity_error")) < 1e-10);
}

TEST_CASE("constraints: lin in the independent coordinate gives sqrt(g/L); trim finds the "
          "bottom") {
    const std::string dir = scratch_dir("cli", "constraints_lin");
    const std::string model = dir + "/pendulum.mbd", out = dir + "/lin.json";
    write_file(model, pendulum_model);
    REQUIRE(exit_status(yamsc + " lin " + model + " --at x=0,z=-0.8 --json > " + out +
                        " 2>/dev/null") == 0);
    const std::string json = read_file(out);
    const double f = std::sqrt(9.81 / 0.8) / (2 * std::acos(-1.0));
    CHECK(std::fabs(json_number(json, "freq_hz") - f) < 1e-12 * f);
    CHECK(json.find("\"states\":[\"x\",\"x'\"]") != std::string::npos);
    REQUIRE(exit_status(yamsc + " trim " + model + " --at x=0.3,z=-0.5 --json > " + out +
                        " 2>/dev/null") == 0);
    const std::vector<double> q = test_support::json_array(read_file(out), "q");
    REQUIRE(q.size() == 2);
    CHECK(std::fabs(q[0]) < 1e-10);
    CHECK(q[1] == doctest::Approx(-0.8).epsilon(1e-12));
    // Options whose model is in all coordinates are refused, with the reason.
    for (const char* option : {" --mbc3", " --hold x", " --format openfast-lin -o "}) {
        CAPTURE(option);
        const std::string extra =
            std::string(option).find("-o") != std::string::npos ? dir + "/case.lin" : "";
        CHECK(exit_status(yamsc + " lin " + model + option + extra + " > " + out + " 2>&1") == 2);
        CHECK(read_file(out).find("does not take a model with constraints") != std::string::npos);
    }
}

TEST_CASE("constraints: a prescribed angle's lambda is the holding torque") {
    const std::string dir = scratch_dir("cli", "constraints_driven");
    const std::string model = dir + "/driven.mbd", csv = dir + "/run.csv";
    write_file(model, driven_model);
    REQUIRE(exit_status(yamsc + " sim " + model + " --tmax 1.3 --dt 1e-3 -o " + csv +
                        " > /dev/null 2>&1") == 0);
    const LastRow r = last_row(csv);
    const double m = 0.7, L = 1.1, g = 9.81, A = 0.4, w = 2.3, t = 1.3;
    const double th = A * std::sin(w * t), thdd = -A * w * w * std::sin(w * t);
    CHECK(r.at("th") == doctest::Approx(th).epsilon(1e-9));
    CHECK(r.at("lambda:drive") ==
          doctest::Approx(m * L * L * thdd + m * g * L * std::sin(th)).epsilon(1e-9));
}

TEST_CASE("constraints: a row that is redundant at the start is an error at its constraint") {
    const std::string dir = scratch_dir("cli", "constraints_redundant");
    const std::string model = dir + "/four_bar.mbd", out = dir + "/out.txt";
    write_file(model,
               read_file(std::string(YAMSC_SOURCE_DIR) + "/tests/model/constraints/four_bar.mbd"));
    // All angles 0: the links lie along x, and the loop's x row moves with none of them.
    CHECK(exit_status(yamsc + " sim " + model + " --tmax 0.1 --dt 0.01 > " + out + " 2>&1") == 1);
    const std::string text = read_file(out);
    CHECK(text.find("four_bar.mbd:") != std::string::npos);
    CHECK(text.find("'closing.x'") != std::string::npos);
    CHECK(text.find("redundant") != std::string::npos);
}
