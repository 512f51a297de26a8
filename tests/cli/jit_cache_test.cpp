// The models `yamsc sim` and `yamsc lin` compile on the fly: only the routines
// the command calls are compiled, the cache is keyed by content (not by how
// the model's path is typed), a cached run derives nothing, and a compile says
// what it compiles and how long that usually takes.
#include "test_files.hpp"

#include "analysis/jit_cache.hpp"

#include <doctest/doctest.h>
#include <yamsc/dynamic_model.hpp>
#include <yamsc/second_order.hpp>

#include <dirent.h>

#include <string>
#include <vector>

using namespace test_support;

namespace {

struct Run {
    int status;
    std::string out, err;
};

/// Runs yamsc in `dir` with its own model cache `cache` (and the environment
/// variables `env`, "NAME=value ...").
Run run_yamsc(const std::string& dir, const std::string& cache, const std::string& args,
              const std::string& env = "") {
    const std::string log = std::string(YAMSC_TEST_BINARY_DIR) + "/jit_cache";
    const int status =
        exit_status("cd '" + dir + "' && YAMSC_CACHE_DIR='" + cache + "' " + env + " " + YAMSC_EXE +
                    " " + args + " >'" + log + ".out' 2>'" + log + ".err'");
    return {status, read_file(log + ".out"), read_file(log + ".err")};
}

std::vector<std::string> libraries(const std::string& cache) {
    std::vector<std::string> out;
    if (DIR* d = ::opendir(cache.c_str())) {
        while (const dirent* e = ::readdir(d)) {
            const std::string name = e->d_name;
            if (name.size() > 3 && name.compare(name.size() - 3, 3, ".so") == 0)
                out.push_back(cache + "/" + name);
        }
        ::closedir(d);
    }
    return out;
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

const std::string pendulum = read_file(std::string(YAMSC_SOURCE_DIR) + "/models/pendulum.mbd");

} // namespace

TEST_CASE("sim compiles rhs and outputs only; cvode adds rhs_jacobian, lin the second-order "
          "model") {
    const std::string dir = scratch_dir("jit_cache", "routines");
    const std::string cache = dir + "/cache";
    write_file(dir + "/pendulum.mbd", pendulum);

    REQUIRE(run_yamsc(dir, cache, "sim pendulum.mbd --tmax 0.1 --dt 0.01").status == 0);
    std::vector<std::string> libs = libraries(cache);
    REQUIRE(libs.size() == 1);
    const yamsc::runtime::SharedModel sim(libs[0]);
    CHECK(sim.routines() == std::vector<std::string>{"rhs", "outputs"});
    // A view of it has no Jacobians, and what needs them says so.
    const yamsc::runtime::ModelView view = sim.view(sim.default_params());
    CHECK(view.rhs);
    CHECK_FALSE(view.jacobians);
    CHECK_THROWS_WITH_AS(yamsc::runtime::second_order_model(view, {0.1}, {0.0}, {}, 0.0),
                         doctest::Contains("compiled without"), std::invalid_argument);

    REQUIRE(run_yamsc(dir, cache, "sim pendulum.mbd --tmax 0.1 --dt 0.01 --method cvode").status ==
            0);
    REQUIRE(libraries(cache).size() == 2);
    REQUIRE(run_yamsc(dir, cache, "lin pendulum.mbd").status == 0);
    libs = libraries(cache);
    REQUIRE(libs.size() == 3);
    std::vector<std::vector<std::string>> sets;
    for (const std::string& lib : libs) sets.push_back(yamsc::runtime::SharedModel(lib).routines());
    auto found = [&](const std::vector<std::string>& set) {
        for (const auto& s : sets)
            if (s == set) return true;
        return false;
    };
    CHECK(found({"rhs", "rhs_jacobian", "outputs"}));
    CHECK(found({"rhs", "rhs_jacobian", "mass_matrix", "forcing", "jacobians"}));
}

TEST_CASE("the cache is keyed by content: another folder or spelling of the path is a hit") {
    const std::string dir = scratch_dir("jit_cache", "content");
    const std::string cache = dir + "/cache";
    REQUIRE(exit_status("mkdir -p '" + dir + "/a' '" + dir + "/b'") == 0);
    write_file(dir + "/a/pendulum.mbd", pendulum);
    write_file(dir + "/b/copy.mbd", pendulum);

    const Run first = run_yamsc(dir, cache, "sim a/pendulum.mbd --tmax 0.1 --dt 0.01");
    REQUIRE(first.status == 0);
    CHECK(has(first.err, "compiling model 'pendulum' (rhs, outputs; "));
    CHECK(has(first.err, "this usually takes about "));
    CHECK(has(first.err, "(no compile timed here yet)"));
    REQUIRE(libraries(cache).size() == 1);

    for (const auto& [where, path] :
         std::vector<std::pair<std::string, std::string>>{{dir + "/a", "pendulum.mbd"},
                                                          {dir + "/a", "./../a//pendulum.mbd"},
                                                          {dir, dir + "/a/pendulum.mbd"},
                                                          {dir + "/b", "copy.mbd"}}) {
        CAPTURE(path);
        const Run again = run_yamsc(where, cache, "sim " + path + " --tmax 0.1 --dt 0.01 -v");
        REQUIRE(again.status == 0);
        CHECK_FALSE(has(again.err, "compiling"));
        // A hit derives nothing: the stages after the checker never run.
        CHECK(has(again.err, "using the compiled model cached in"));
        CHECK_FALSE(has(again.err, "derived the equations"));
        CHECK(again.out == first.out);
    }
    CHECK(libraries(cache).size() == 1);

    // The derivation (GiNaC, CLN) is a module loaded only to derive: a hit never
    // loads it (the cache key holds its file's stamp, read without loading it).
    const std::string nowhere = "YAMSC_DERIVATION_MODULE=/nonexistent/libyamsc-derivation.so";
    const Run traced =
        run_yamsc(dir + "/a", cache, "sim pendulum.mbd --tmax 0.1 --dt 0.01", "LD_DEBUG=files");
    REQUIRE(traced.status == 0);
    CHECK(has(traced.err, "file=")); // the dynamic loader's trace is there
    CHECK_FALSE(has(traced.err, "libyamsc-derivation"));
    CHECK_FALSE(has(traced.err, "libginac"));
    CHECK_FALSE(has(traced.err, "libcln"));
    // A model that must be derived says which module it could not find (exit 70:
    // a broken installation, not the model's fault).
    write_file(dir + "/a/other.mbd", pendulum + "\n# another model\n");
    const Run missing = run_yamsc(dir + "/a", cache, "sim other.mbd --tmax 0.1 --dt 0.01", nowhere);
    CHECK(missing.status == 70);
    CHECK(has(missing.err, "cannot find the derivation module"));
    CHECK(has(missing.err, "/nonexistent/libyamsc-derivation.so: not found"));

    // Any change of the text is another model, and the estimate now comes from here.
    write_file(dir + "/b/copy.mbd", pendulum + "\n# a comment\n");
    const Run changed = run_yamsc(dir + "/b", cache, "sim copy.mbd --tmax 0.1 --dt 0.01");
    REQUIRE(changed.status == 0);
    CHECK(has(changed.err, "compiling model"));
    CHECK(has(changed.err, " here;"));
    CHECK(libraries(cache).size() == 2);
}

TEST_CASE("a model's data files are part of its key") {
    const std::string dir = scratch_dir("jit_cache", "data");
    const std::string cache = dir + "/cache";
    // A model built from an ElastoDyn tower file: its text stays, the file changes.
    const std::string models = std::string(YAMSC_SOURCE_DIR) + "/models/";
    const std::string tower = "data/NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat";
    REQUIRE(exit_status("mkdir -p '" + dir + "/data'") == 0);
    write_file(dir + "/m.mbd", read_file(models + "nrel5mw_land_2dof.mbd"));
    write_file(dir + "/" + tower, read_file(models + tower));
    REQUIRE(run_yamsc(dir, cache, "sim m.mbd --tmax 0.01 --dt 0.01").status == 0);
    REQUIRE(libraries(cache).size() == 1);
    CHECK_FALSE(has(run_yamsc(dir, cache, "sim m.mbd --tmax 0.01 --dt 0.01").err, "compiling"));
    write_file(dir + "/" + tower, read_file(models + tower) + "\n");
    CHECK(has(run_yamsc(dir, cache, "sim m.mbd --tmax 0.01 --dt 0.01").err, "compiling"));
    CHECK(libraries(cache).size() == 2);
}

TEST_CASE("compile estimates: the median rate of the last compiles recorded") {
    const std::string dir = scratch_dir("jit_cache", "estimate");
    const yamsc::analysis::ModelCache cache(dir + "/cache");
    const yamsc::analysis::CompileEstimate none = cache.estimate(1'000'000);
    CHECK_FALSE(none.measured_here);
    CHECK(none.seconds > 0);
    cache.record_compile(1'000'000, 10.0); // 10 s/MB
    cache.record_compile(2'000'000, 60.0); // 30 s/MB
    cache.record_compile(500'000, 10.0);   // 20 s/MB
    const yamsc::analysis::CompileEstimate e = cache.estimate(3'000'000);
    CHECK(e.measured_here);
    CHECK(e.seconds == doctest::Approx(60.0));
}

TEST_CASE("a file a build reads is keyed by its contents' stamp, executable or not") {
    // The units of `yamsc fmu` link the runtime's archives: a rebuilt archive
    // (not executable, so not a program to look up) must change the unit's key.
    const std::string dir = scratch_dir("jit_cache", "file_identity");
    const std::string archive = dir + "/libsome.a";
    write_file(archive, "one");
    const std::string first = yamsc::analysis::file_identity(archive);
    CHECK(has(first, archive + " -> "));
    CHECK_FALSE(has(first, "-> ?"));
    // Another spelling of the path: the same file's stamp after the arrow.
    const auto stamp = [](const std::string& identity) {
        return identity.substr(identity.find(" -> "));
    };
    CHECK(stamp(yamsc::analysis::file_identity(dir + "/./libsome.a")) == stamp(first));
    write_file(archive, "longer");
    CHECK(yamsc::analysis::file_identity(archive) != first);
    CHECK(has(yamsc::analysis::file_identity(dir + "/missing.a"), "-> ?"));
}
