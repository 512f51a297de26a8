// The bad-input corpus (tests/bad/): one model per diagnostic, its first line
// `# expect: <the first error, as printed>` (what the case is about), and beside
// it X.expected, the whole diagnostic output (messages, source lines, carets,
// notes) refreshed by scripts/update-bad-expected.sh. Each must fail with exit
// status 1, print exactly that output, and write nothing; every diagnostic kind
// must have a case.
#include "diag/diagnostics.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <dirent.h>
#include <fstream>
#include <set>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

const std::string bad_dir = std::string(YAMSC_SOURCE_DIR) + "/tests/bad";
const std::string work = std::string(YAMSC_TEST_BINARY_DIR) + "/bad";

struct Run {
    int status = -1;
    std::string err;
};

/// Runs yamsc with `args` in `dir`, capturing stderr.
Run run_yamsc(const std::string& dir, const std::string& args) {
    std::string log = work + "/stderr.txt";
    std::string cmd = "cd " + dir + " && " + YAMSC_EXE + " " + args + " >/dev/null 2>" + log;
    Run r;
    int raw = std::system(cmd.c_str());
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream in(log);
    r.err.assign(std::istreambuf_iterator<char>(in), {});
    return r;
}

std::vector<std::string> corpus() {
    std::vector<std::string> out;
    DIR* d = opendir(bad_dir.c_str());
    REQUIRE(d);
    while (dirent* e = readdir(d)) {
        std::string n = e->d_name;
        if (n.size() > 4 && n.compare(n.size() - 4, 4, ".mbd") == 0) out.push_back(n);
    }
    closedir(d);
    std::sort(out.begin(), out.end());
    return out;
}

std::string expectation(const std::string& file) {
    std::ifstream in(bad_dir + "/" + file);
    std::string line;
    std::getline(in, line);
    const std::string tag = "# expect: ";
    REQUIRE_MESSAGE(line.rfind(tag, 0) == 0, file << " must start with '# expect: '");
    return line.substr(tag.size());
}

/// The whole diagnostic output expected of `file` (X.mbd -> X.expected).
std::string expected_output(const std::string& file) {
    const std::string path = bad_dir + "/" + file.substr(0, file.size() - 4) + ".expected";
    std::ifstream in(path);
    REQUIRE_MESSAGE(in.good(), path << " is missing: run scripts/update-bad-expected.sh");
    return std::string(std::istreambuf_iterator<char>(in), {});
}

} // namespace

TEST_CASE(
    "every bad input fails with its diagnostic, exit 1 and no output; every kind is covered") {
    std::system(("mkdir -p " + work).c_str());
    std::set<std::string> kinds_seen;
    for (const auto& file : corpus()) {
        CAPTURE(file);
        Run check = run_yamsc(bad_dir, "check " + file);
        CHECK(check.status == 1);
        CHECK(check.err.find(expectation(file)) != std::string::npos);
        CHECK(check.err == expected_output(file));
        CHECK(check.err.find('^') != std::string::npos); // the caret under the source line
        for (std::size_t open = check.err.find(" ["); open != std::string::npos;
             open = check.err.find(" [", open + 1)) {
            auto close = check.err.find("]\n", open);
            if (close != std::string::npos)
                kinds_seen.insert(check.err.substr(open + 2, close - open - 2));
        }
        std::string out = work + "/out.cpp";
        std::remove(out.c_str());
        Run compile = run_yamsc(bad_dir, file + " -o " + out);
        CHECK(compile.status == 1);
        CHECK(access(out.c_str(), F_OK) != 0);
    }
    // A file that cannot be read.
    Run missing = run_yamsc(work, "check does_not_exist.mbd");
    CHECK(missing.status == 1);
    CHECK(missing.err.find("cannot read 'does_not_exist.mbd'") != std::string::npos);
    if (missing.err.find("[io]") != std::string::npos) kinds_seen.insert("io");

    for (auto kind : yamsc::diag::all_kinds()) {
        std::string name(yamsc::diag::kind_name(kind));
        INFO("diagnostic kind '" << name << "' has no case in tests/bad/");
        CHECK(kinds_seen.count(name) == 1);
    }
}

TEST_CASE("every expected output in tests/bad/ belongs to a model of the corpus") {
    DIR* d = opendir(bad_dir.c_str());
    REQUIRE(d);
    int expected_files = 0;
    while (dirent* e = readdir(d)) {
        std::string n = e->d_name;
        const std::string ext = ".expected";
        if (n.size() <= ext.size() || n.compare(n.size() - ext.size(), ext.size(), ext) != 0)
            continue;
        ++expected_files;
        const std::string model = n.substr(0, n.size() - ext.size()) + ".mbd";
        INFO(n << " has no model " << model);
        CHECK(access((bad_dir + "/" + model).c_str(), F_OK) == 0);
    }
    closedir(d);
    CHECK(expected_files == static_cast<int>(corpus().size()));
}

TEST_CASE("usage errors exit 2, and a compile failure leaves an existing output untouched") {
    std::system(("mkdir -p " + work).c_str());
    CHECK(run_yamsc(work, "").status == 2);
    CHECK(run_yamsc(work, "sim x.mbd --tmax 1").status == 2);
    CHECK(run_yamsc(work, "check a.mbd --bogus").status == 2);
    CHECK(run_yamsc(work,
                    "eval " + std::string(YAMSC_SOURCE_DIR) + "/models/pendulum.mbd --q 1,2 --json")
              .status == 2);
    std::string out = work + "/kept.cpp";
    {
        std::ofstream f(out);
        f << "previous";
    }
    CHECK(run_yamsc(bad_dir, "dof_unused.mbd -o " + out).status == 1);
    std::ifstream in(out);
    std::string content((std::istreambuf_iterator<char>(in)), {});
    CHECK(content == "previous");
}

TEST_CASE("a parameter without a value is named") {
    std::system(("mkdir -p " + work).c_str());
    {
        std::ofstream f(work + "/nodefault.mbd");
        f << "model nd\nparam L\ndof q\nrigid b { mass = 1; com = (0, 0, -L) }\njoint ground -> b "
             "{ rotate y q }\n";
    }
    Run r = run_yamsc(work, "eval nodefault.mbd --json");
    CHECK(r.status == 1);
    CHECK(r.err.find("parameter without a value: L") != std::string::npos);
    CHECK(run_yamsc(work, "eval nodefault.mbd --set L=2 --json").status == 0);
}
