// What build systems rely on when they run `yamsc MODEL -o FILE` (issue 6, item 4):
// the `Source digest` in generated headers is the digest of the model and every
// data file it read, so it changes exactly when they do; the depfile names the
// outputs, the model and those data files (spaces escaped); the bytes do not
// depend on the working directory, the output folder or the file times; and no
// temporary file is left behind, whether the run succeeds or fails. Inputs that
// are not files (a folder, /dev/zero), as the model or as its data, are errors too.
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace {

using test_support::temporaries;

const std::string source_dir = YAMSC_SOURCE_DIR;
// A space in the folder name: depfiles must escape it.
const std::string work = std::string(YAMSC_TEST_BINARY_DIR) + "/outputs dir";

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void spit(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::string quoted(const std::string& path) {
    return "'" + path + "'";
}

/// Runs yamsc in `dir` with `args`; returns its exit status.
int yamsc(const std::string& dir, const std::string& args) {
    std::string cmd = "cd " + quoted(dir) + " && " + YAMSC_EXE + " " + args + " >" +
                      quoted(work + "/stdout.txt") + " 2>" + quoted(work + "/stderr.txt");
    int raw = std::system(cmd.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

/// FNV-1a, 64 bit, as 16 hex digits: the digest generated headers carry.
std::string fnv1a(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

/// The value of the `// Source digest: "..."` line of a generated file.
std::string digest_in(const std::string& text) {
    const std::string tag = "// Source digest: \"";
    auto at = text.find(tag);
    if (at == std::string::npos) return "(none)";
    at += tag.size();
    return text.substr(at, text.find('"', at) - at);
}

void fresh_dir(const std::string& dir) {
    std::system(("rm -rf " + quoted(dir) + " && mkdir -p " + quoted(dir)).c_str());
}

const char* mast_model = "model mast \"A clamped flexible mast\"\n"
                         "dof q1\n"
                         "flexible mast { sid = \"mast.sid\"; modes = (q1) }\n"
                         "joint ground -> mast\n";

/// A copy of tests/sid/data/minimal.sid, Me = 25 and Ke = 2500, under `dir`.
void write_mast(const std::string& dir) {
    spit(dir + "/mast.mbd", mast_model);
    spit(dir + "/mast.sid", slurp(source_dir + "/tests/sid/data/minimal.sid"));
}

} // namespace

TEST_CASE("the source digest is the digest of the model text and of every data file it read") {
    fresh_dir(work);
    // A rigid model: the model text alone.
    const std::string pendulum = source_dir + "/models/pendulum.mbd";
    REQUIRE(yamsc(work, quoted(pendulum) + " -o p.cpp --header p.hpp") == 0);
    CHECK(digest_in(slurp(work + "/p.cpp")) == fnv1a(slurp(pendulum)));
    CHECK(digest_in(slurp(work + "/p.hpp")) == fnv1a(slurp(pendulum)));
    REQUIRE(yamsc(work, quoted(pendulum) + " -o p.c --header p.h") == 0);
    CHECK(digest_in(slurp(work + "/p.c")) == fnv1a(slurp(pendulum)));

    // A flexible model: the model text, then each data file after a newline.
    write_mast(work);
    REQUIRE(yamsc(work, "mast.mbd -o mast.cpp") == 0);
    const std::string first = slurp(work + "/mast.cpp");
    CHECK(digest_in(first) == fnv1a(std::string(mast_model) + "\n" + slurp(work + "/mast.sid")));

    // Only the contents count: a touched SID gives the same bytes ...
    std::system(("touch " + quoted(work + "/mast.sid")).c_str());
    REQUIRE(yamsc(work, "mast.mbd -o mast.cpp") == 0);
    CHECK(slurp(work + "/mast.cpp") == first);

    // ... an edited one (Ke 2500 -> 3600) a new digest and new equations.
    std::string sid = slurp(work + "/mast.sid");
    auto at = sid.find("= 2500.0");
    REQUIRE(at != std::string::npos);
    spit(work + "/mast.sid", sid.replace(at, 8, "= 3600.0"));
    REQUIRE(yamsc(work, "mast.mbd -o mast.cpp") == 0);
    const std::string second = slurp(work + "/mast.cpp");
    CHECK(digest_in(second) != digest_in(first));
    CHECK(digest_in(second) == fnv1a(std::string(mast_model) + "\n" + slurp(work + "/mast.sid")));
    CHECK(second.find("3600") != std::string::npos);
    CHECK(first.find("3600") == std::string::npos);
}

TEST_CASE("the depfile names the outputs, the model and every data file, escaped for make") {
    fresh_dir(work);
    write_mast(work);
    REQUIRE(yamsc(work, quoted(work + "/mast.mbd") + " -o " + quoted(work + "/m.cpp") +
                            " --header " + quoted(work + "/m.hpp") + " --depfile " +
                            quoted(work + "/m.d")) == 0);
    auto escaped = [](std::string s) {
        for (std::size_t at = s.find(' '); at != std::string::npos; at = s.find(' ', at + 2))
            s.replace(at, 1, "\\ ");
        return s;
    };
    const std::string expected = escaped(work + "/m.cpp") + " " + escaped(work + "/m.hpp") + ": " +
                                 escaped(work + "/mast.mbd") + " " + escaped(work + "/mast.sid") +
                                 "\n";
    CHECK(slurp(work + "/m.d") == expected);

    // ElastoDyn files count too: the blade model reads one.
    REQUIRE(yamsc(source_dir, "models/nrel5mw_blade.mbd -o " + quoted(work + "/b.cpp") +
                                  " --depfile " + quoted(work + "/b.d")) == 0);
    CHECK(slurp(work + "/b.d") == escaped(work + "/b.cpp") +
                                      ": models/nrel5mw_blade.mbd "
                                      "models/data/NRELOffshrBsline5MW_Blade.dat\n");
    // A model that fails writes no depfile either.
    CHECK(yamsc(source_dir + "/tests/bad", "dof_unused.mbd -o " + quoted(work + "/bad.cpp") +
                                               " --depfile " + quoted(work + "/bad.d")) == 1);
    CHECK(slurp(work + "/bad.d").empty());
    CHECK(temporaries(work).empty());

    // '#' and '$' are escaped as make and Ninja read them.
    const std::string odd = work + "/odd #1 $HOME";
    REQUIRE(std::system(("mkdir -p " + quoted(odd)).c_str()) == 0);
    write_mast(odd);
    REQUIRE(yamsc(work, quoted(odd + "/mast.mbd") + " -o " + quoted(odd + "/out.cpp") +
                            " --depfile " + quoted(odd + "/out.d")) == 0);
    const std::string folder = escaped(work) + "/odd\\ \\#1\\ $$HOME"; // work has no # or $
    CHECK(slurp(odd + "/out.d") ==
          folder + "/out.cpp: " + folder + "/mast.mbd " + folder + "/mast.sid\n");
}

TEST_CASE("the bytes do not depend on the working directory or the output folder") {
    fresh_dir(work);
    fresh_dir(work + "/a");
    fresh_dir(work + "/b/deeper");
    const std::string model = source_dir + "/models/double_pendulum.mbd";
    REQUIRE(yamsc(work + "/a", quoted(model) + " -o m.cpp --header m.hpp") == 0);
    REQUIRE(yamsc("/", quoted(model) + " -o " + quoted(work + "/b/deeper/m.cpp") + " --header " +
                           quoted(work + "/b/deeper/m.hpp")) == 0);
    for (const char* ext : {".cpp", ".hpp"}) {
        CAPTURE(ext);
        const std::string a = slurp(work + "/a/m" + ext);
        CHECK(!a.empty());
        CHECK(a == slurp(work + "/b/deeper/m" + ext));
    }
}

TEST_CASE("no temporary file is left behind, and a failed write leaves no output") {
    fresh_dir(work);
    const std::string model = source_dir + "/models/pendulum.mbd";
    REQUIRE(yamsc(work, quoted(model) + " -o ok.c --header ok.h --depfile ok.d") == 0);
    CHECK(temporaries(work).empty());

    // The output folder does not exist: exit 1, a message naming the file, nothing written.
    CHECK(yamsc(work, quoted(model) + " -o missing/out.cpp") == 1);
    CHECK(slurp(work + "/stderr.txt").find("cannot write 'missing/out.cpp'") != std::string::npos);
    CHECK(temporaries(work).empty());

    // The target is a folder: the temporary file is written, the rename fails, and
    // the temporary file is removed again.
    fresh_dir(work + "/taken.cpp");
    CHECK(yamsc(work, quoted(model) + " -o taken.cpp") == 1);
    CHECK(temporaries(work).empty());

    // A model with an error: exit 1 and no file at all.
    CHECK(yamsc(source_dir + "/tests/bad", "syntax_unclosed_block.mbd -o " +
                                               quoted(work + "/never.cpp") + " --header " +
                                               quoted(work + "/never.hpp")) == 1);
    CHECK(slurp(work + "/never.cpp").empty());
    CHECK(slurp(work + "/never.hpp").empty());
    CHECK(temporaries(work).empty());
    CHECK(temporaries(source_dir + "/tests/bad").empty());
}

TEST_CASE("a folder or an endless file as the model is an error, not a hang") {
    fresh_dir(work);
    CHECK(yamsc(work, "check " + quoted(work)) == 1);
    CHECK(slurp(work + "/stderr.txt").find("it is a folder") != std::string::npos);
    // /dev/zero never ends: reading stops at the largest input any reader accepts.
    CHECK(yamsc(work, "check /dev/zero") == 1);
    CHECK(slurp(work + "/stderr.txt").find("'/dev/zero' is larger than 256 MiB") !=
          std::string::npos);
    CHECK(yamsc(work, "/dev/zero -o never.cpp") == 1);
    CHECK(slurp(work + "/never.cpp").empty());
}

TEST_CASE("a header and its source are replaced together or not at all") {
    fresh_dir(work);
    spit(work + "/keep.h", "old header");
    // The source cannot be written (no such folder): the header stays as it was.
    CHECK(yamsc(work, quoted(source_dir + "/models/pendulum.mbd") +
                          " -o missing/p.c --header keep.h") == 1);
    CHECK(slurp(work + "/keep.h") == "old header");
    CHECK(slurp(work + "/stderr.txt").find("cannot write 'missing/p.c'") != std::string::npos);
    CHECK(temporaries(work).empty());
}

TEST_CASE("a folder or an endless file named as a model's data is an error at its location") {
    fresh_dir(work);
    spit(work + "/endless.mbd", "model m\ndof q\n"
                                "flexible tower { sid = \"/dev/zero\"; modes = (q) }\n"
                                "joint ground -> tower\n");
    CHECK(yamsc(work, "check " + quoted(work + "/endless.mbd")) == 1);
    CHECK(slurp(work + "/stderr.txt")
              .find("endless.mbd:3:24: error: '/dev/zero' is larger than 256 MiB") !=
          std::string::npos);
    spit(work + "/folder.mbd", "model m\ndof q\n"
                               "flexible tower { sid = \".\"; modes = (q) }\n"
                               "joint ground -> tower\n");
    CHECK(yamsc(work, "check " + quoted(work + "/folder.mbd")) == 1);
    CHECK(slurp(work + "/stderr.txt").find("folder.mbd:3:24: error: cannot read") !=
          std::string::npos);
    CHECK(slurp(work + "/stderr.txt").find("it is a folder") != std::string::npos);
}
