// `yamsc lin` and `yamsc sim` end to end: the pendulum's natural frequency
// sqrt(g/L)/2π from the generated Jacobian, and a CSV written by sim.
#include "json_values.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <vector>

using test_support::json_matrix;
using test_support::json_number;
using test_support::json_numbers_of;

namespace {

std::string capture(const std::string& args) {
    std::string out = std::string(YAMSC_TEST_BINARY_DIR) + "/cli_out.txt";
    std::string cmd = std::string(YAMSC_EXE) + " " + args + " > " + out + " 2>/dev/null";
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::ifstream in(out);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

double number_after(const std::string& text, const std::string& key) {
    auto pos = text.find(key);
    REQUIRE(pos != std::string::npos);
    return std::stod(text.substr(pos + key.size()));
}

} // namespace

TEST_CASE("lin: the pendulum's matrices and frequency sqrt(g/L)/2pi, for any L given with --set") {
    const std::string model = std::string(YAMSC_SOURCE_DIR) + "/models/pendulum.mbd";
    const double m = 1.0, g = 9.81;
    for (double L : {1.0, 2.5}) {
        CAPTURE(L);
        const std::string json =
            capture("lin " + model + " --set L=" + std::to_string(L) + " --json");
        // About the hanging equilibrium: m L^2 theta'' + m g L theta = 0.
        const auto M0 = json_matrix(json, "M0"), C0 = json_matrix(json, "C0"),
                   K0 = json_matrix(json, "K0");
        REQUIRE(M0.size() == 1);
        REQUIRE(M0[0].size() == 1);
        CHECK(M0[0][0] == doctest::Approx(m * L * L).epsilon(1e-14));
        CHECK(C0 == std::vector<std::vector<double>>{{0.0}});
        REQUIRE(K0.size() == 1);
        REQUIRE(K0[0].size() == 1);
        CHECK(K0[0][0] == doctest::Approx(m * g * L).epsilon(1e-14));
        CHECK(json_number(json, "freq_hz") ==
              doctest::Approx(std::sqrt(g / L) / (2 * M_PI)).epsilon(1e-12));
    }
}

TEST_CASE("lin: a free rotor azimuth is a rigid-body mode") {
    std::string json =
        capture("lin " + std::string(YAMSC_SOURCE_DIR) + "/models/nrel5mw_spar_rigid.mbd --json");
    // The azimuth has no stiffness or damping; nor, in this model, has surge.
    const auto M0 = json_matrix(json, "M0"), C0 = json_matrix(json, "C0"),
               K0 = json_matrix(json, "K0");
    REQUIRE(K0.size() == 3);
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(K0[i][2] == 0);
        CHECK(K0[2][i] == 0);
        CHECK(C0[i][2] == 0);
    }
    CHECK(M0[0][2] == 0);
    CHECK(M0[1][2] == 0);
    CHECK(K0[0][0] == 0);
    CHECK(M0[2][2] > 0);
    // Two rigid-body modes (surge, azimuth) at 0 Hz, then platform pitch: the
    // non-zero root of det(K - w^2 M) = 0 over surge and pitch.
    std::vector<bool> rigid;
    for (auto at = json.find("\"rigid_body\":"); at != std::string::npos;
         at = json.find("\"rigid_body\":", at + 1))
        rigid.push_back(json.compare(at + 13, 4, "true") == 0);
    CHECK(rigid == std::vector<bool>{true, true, false});
    const double det_m = M0[0][0] * M0[1][1] - M0[0][1] * M0[1][0];
    const double w2 =
        (M0[0][0] * K0[1][1] + M0[1][1] * K0[0][0] - M0[0][1] * K0[1][0] - M0[1][0] * K0[0][1]) /
        det_m;
    const auto freqs = json_numbers_of(json, "freq_hz");
    REQUIRE(freqs.size() == 3);
    CHECK(freqs[0] == 0);
    CHECK(freqs[1] == 0);
    CHECK(freqs[2] == doctest::Approx(std::sqrt(w2) / (2 * M_PI)).epsilon(1e-9));
}

TEST_CASE("sim: writes the CSV header of cli.md and the initial state") {
    std::string csv = std::string(YAMSC_TEST_BINARY_DIR) + "/dp.csv";
    std::remove(csv.c_str());
    capture("sim " + std::string(YAMSC_SOURCE_DIR) +
            "/models/double_pendulum.mbd --tmax 0.1 --dt 0.01 --ic \"th1=30deg,th2'=0.5\" -o " +
            csv);
    std::ifstream in(csv);
    std::string header, first;
    std::getline(in, header);
    std::getline(in, first);
    CHECK(header == "time,th1,th2,th1',th2',x_tip,z_tip,v_tip");
    CHECK(first.rfind("0,0.5235987756,0,0,0.5,", 0) == 0);
    int rows = 1;
    for (std::string line; std::getline(in, line);) ++rows;
    CHECK(rows == 11);
}

TEST_CASE("sim: --method abm4 and --dt-out, rows every --dt-out from the same run") {
    const std::string model = std::string(YAMSC_SOURCE_DIR) + "/models/double_pendulum.mbd";
    const std::string dir = std::string(YAMSC_TEST_BINARY_DIR) + "/";
    auto lines = [](const std::string& path) {
        std::ifstream in(path);
        std::vector<std::string> out;
        for (std::string line; std::getline(in, line);) out.push_back(line);
        return out;
    };
    for (const char* method : {"rk4", "abm4"}) {
        CAPTURE(method);
        const std::string every = dir + "dp_every.csv", sparse = dir + "dp_sparse.csv";
        const std::string run =
            "sim " + model + " --tmax 0.5 --dt 0.01 --ic th1=30deg --method " + method + " -o ";
        capture(run + every);
        capture(run + sparse + " --dt-out 0.05");
        const auto all = lines(every), some = lines(sparse);
        REQUIRE(all.size() == 52); // header and 51 rows
        REQUIRE(some.size() == 12);
        CHECK(some[0] == all[0]); // the header
        for (std::size_t i = 1; i < some.size(); ++i) CHECK(some[i] == all[5 * (i - 1) + 1]);
    }
    // ABM4 differs from RK4 after its three RK4 steps only by its truncation error.
    const std::string summary_rk4 = capture("sim " + model + " --tmax 1 --dt 0.001 --ic th1=30deg");
    const std::string summary_abm4 =
        capture("sim " + model + " --tmax 1 --dt 0.001 --ic th1=30deg --method abm4");
    CHECK(summary_rk4 != summary_abm4);
    CHECK(number_after(summary_abm4, "\nth1 ") ==
          doctest::Approx(number_after(summary_rk4, "\nth1 ")).epsilon(1e-9));
    const std::string bad = std::string(YAMSC_EXE) + " sim " + model +
                            " --tmax 1 --dt 0.01 --dt-out 0.015 > /dev/null 2>&1";
    CHECK(WEXITSTATUS(std::system(bad.c_str())) == 2);
}

TEST_CASE("sim: --coupling loose couples load blocks only; its options are checked") {
    const std::string model = std::string(YAMSC_SOURCE_DIR) + "/models/double_pendulum.mbd";
    const std::string run = "sim " + model + " --tmax 0.5 --dt 0.01 --ic th1=30deg --method abm4";
    // No block: the same run, to the last digit.
    CHECK(capture(run + " --coupling loose --interp-order 1") == capture(run));
    for (const char* options : {"--coupling loose --method cvode", "--interp-order 1",
                                "--coupling loose --interp-order 3",
                                "--coupling loose --interp-order 1.5", "--coupling medium"}) {
        CAPTURE(options);
        const std::string bad = std::string(YAMSC_EXE) + " sim " + model + " --tmax 1 --dt 0.01 " +
                                options + " > /dev/null 2>&1";
        CHECK(WEXITSTATUS(std::system(bad.c_str())) == 2);
    }
}
