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

TEST_CASE("symbolic modes: shape integrals as parameters, values from a SID at run time") {
    const std::string dir = YAMSC_TEST_BINARY_DIR;
    const std::string tower = std::string(YAMSC_SOURCE_DIR) +
                              "/models/data/NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat";
    REQUIRE(run("sid --elastodyn-tower " + tower + " --length 87.6 --modes fa1 -o " + dir +
                "/sym_tower.sid") == 0);
    // A stiffer tower: the same file scaled by a shorter length.
    REQUIRE(run("sid --elastodyn-tower " + tower + " --length 60 --modes fa1 -o " + dir +
                "/sym_short.sid") == 0);
    auto write_model = [&](const std::string& name, const std::string& body) {
        std::ofstream(dir + "/" + name) << "model " << name.substr(0, name.size() - 4) << "\n"
                                        << "dof q\ngravity (0, 0, -9.807)\n"
                                        << body << "\njoint ground -> tower\n";
    };
    write_model("num_tower.mbd", "flexible tower { sid = \"sym_tower.sid\"; modes = (q) }");
    write_model("sym_tower.mbd",
                "flexible tower { symbolic modes = (q); sid = \"sym_tower.sid\" }");
    write_model("short_tower.mbd", "flexible tower { sid = \"sym_short.sid\"; modes = (q) }");
    auto freq = [&](const std::string& args) {
        REQUIRE(run("lin " + args + " --json") == 0);
        std::string json = slurp(dir + "/sid_out.txt");
        auto pos = json.find("\"freq_hz\":");
        REQUIRE(pos != std::string::npos);
        return std::stod(json.substr(pos + 10));
    };
    const double numeric = freq(dir + "/num_tower.mbd");
    CHECK(freq(dir + "/sym_tower.mbd") == doctest::Approx(numeric).epsilon(1e-12));
    const double shorter = freq(dir + "/short_tower.mbd");
    CHECK(shorter > 1.5 * numeric);
    CHECK(freq(dir + "/sym_tower.mbd --sid tower=" + dir + "/sym_short.sid") ==
          doctest::Approx(shorter).epsilon(1e-12));
    // The generated code names the shape integrals like the paper's Appendix E.
    REQUIRE(run(dir + "/sym_tower.mbd -o " + dir + "/sym_tower.cpp") == 0);
    std::string code = slurp(dir + "/sym_tower.cpp");
    CHECK(code.find("tower_Me_1_1") != std::string::npos);
    CHECK(code.find("tower_Ke_1_1") != std::string::npos);
    CHECK(code.find("tower_Ct1_1_3_1") != std::string::npos); // K_gt: own weight
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
