// `yamsc lin` and `yamsc sim` end to end: the pendulum's natural frequency
// sqrt(g/L)/2π from the generated Jacobian, and a CSV written by sim.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <vector>

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

TEST_CASE("lin: the pendulum's frequency is sqrt(g/L)/2pi, for any L given with --set") {
    std::string model = std::string(YAMSC_SOURCE_DIR) + "/models/pendulum.mbd";
    for (double L : {1.0, 2.5}) {
        std::string json = capture("lin " + model + " --set L=" + std::to_string(L) + " --json");
        double f = number_after(json, "\"freq_hz\":");
        CHECK(f == doctest::Approx(std::sqrt(9.81 / L) / (2 * M_PI)).epsilon(1e-12));
        CHECK(json.find("\"K0\":[[" + std::string(L == 1.0 ? "9.81" : "24.52")) !=
              std::string::npos);
    }
}

TEST_CASE("lin: a free rotor azimuth is a rigid-body mode") {
    std::string json =
        capture("lin " + std::string(YAMSC_SOURCE_DIR) + "/models/nrel5mw_spar_rigid.mbd --json");
    CHECK(json.find("\"rigid_body\":true") != std::string::npos);
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
