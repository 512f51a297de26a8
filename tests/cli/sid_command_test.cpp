// `yamsc sid` end to end: the SID of the NREL 5-MW onshore tower from its
// ElastoDyn file, written in the standard text format and read back by a model.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <sys/wait.h>

namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

int run(const std::string& args) {
    std::string cmd = std::string(YAMSC_EXE) + " " + args + " 2>" + YAMSC_TEST_BINARY_DIR +
                      "/sid_err.txt >" + YAMSC_TEST_BINARY_DIR + "/sid_out.txt";
    return std::system(cmd.c_str());
}

} // namespace

TEST_CASE("sid: the NREL 5-MW tower's SID, written and used by a model") {
    const std::string dir = YAMSC_TEST_BINARY_DIR;
    const std::string sid = dir + "/tower.sid";
    std::remove(sid.c_str());
    REQUIRE(run("sid --elastodyn-tower " + std::string(YAMSC_SOURCE_DIR) +
                "/models/data/NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat --length 87.6 "
                "--modes fa1 --stations 20 -o " +
                sid) == 0);
    std::string text = slurp(sid);
    CHECK(text.rfind("part", 0) == 0);
    CHECK(text.find("new modal") != std::string::npos);
    CHECK(text.find("nelastq") != std::string::npos);
    CHECK(text.find("new node = 20") != std::string::npos);
    // A model on that SID gives the tower's first fore-aft frequency
    // sqrt((Ke + g Kgt)/Me)/2π with Me 5.40e4, Ke 1.91e6, Kgt -1.04e4 (about 0.94 Hz).
    std::ofstream(dir + "/tower_only.mbd")
        << "model tower_only\n"
           "dof q\n"
           "gravity (0, 0, -9.807)\n"
           "flexible tower { sid = \"tower.sid\"; modes = (q) }\n"
           "joint ground -> tower\n";
    REQUIRE(run("lin " + dir + "/tower_only.mbd --json") == 0);
    std::string json = slurp(dir + "/sid_out.txt");
    auto pos = json.find("\"freq_hz\":");
    REQUIRE(pos != std::string::npos);
    double f = std::stod(json.substr(pos + 10));
    CHECK(f == doctest::Approx(std::sqrt((1.91e6 - 1.04e4) / 5.40e4) / (2 * M_PI)).epsilon(0.01));
}

TEST_CASE("sid: usage errors exit 2, bad files exit 1 and write nothing") {
    const std::string out = std::string(YAMSC_TEST_BINARY_DIR) + "/never.sid";
    std::remove(out.c_str());
    CHECK(WEXITSTATUS(run("sid --length 10 -o " + out)) == 2);
    CHECK(WEXITSTATUS(run("sid --elastodyn-tower /no/such/file --length 10 -o " + out)) == 1);
    CHECK(WEXITSTATUS(run("sid --elastodyn-tower " + std::string(YAMSC_SOURCE_DIR) +
                          "/models/nrel5mw_blade.mbd --length 10 -o " + out)) == 1);
    CHECK_FALSE(std::ifstream(out).good());
}
