// `yamsc turbulence` as a library call: the file it writes, its refusals (an
// output that is its input, a field it cannot make) leaving nothing behind.
#include "analysis/commands.hpp"
#include "diag/errors.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <cstring>
#include <filesystem>
#include <sstream>

using namespace yamsc;

namespace {

driver::TurbulenceOptions small_options(const std::string& output) {
    driver::TurbulenceOptions o;
    o.output = output;
    o.characteristic = driver::TurbulenceCharacteristicOption::A;
    o.speed = 10;
    o.hub_height = 60;
    o.ny = 3;
    o.nz = 4;
    o.width = 40;
    o.height = 30;
    o.time_step = 0.25;
    o.time = 30;
    o.seed = -5;
    o.periodic = true;
    return o;
}

std::int32_t i32_at(const std::string& s, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i)
        v = v << 8 | static_cast<unsigned char>(s[at + static_cast<std::size_t>(i)]);
    return static_cast<std::int32_t>(v);
}

} // namespace

TEST_CASE("turbulence from options alone: a periodic .bts of the FFT's length") {
    const std::string dir = test_support::scratch_dir("turbulence", "options");
    const std::string bts = dir + "/a.bts";
    std::ostringstream out, err;
    CHECK(analysis::turbulence(small_options(bts), out, err) == 0);
    const std::string s = test_support::read_file(bts);
    REQUIRE(s.size() > 70);
    CHECK(s[0] == 8); // periodic
    CHECK(i32_at(s, 2) == 4);
    CHECK(i32_at(s, 6) == 3);
    CHECK(i32_at(s, 10) == 0);
    CHECK(i32_at(s, 14) == 120); // 30 s / 0.25 s = 120 = 2 x 60, a product of small primes
    const std::int32_t description = i32_at(s, 66);
    CHECK(s.size() == 70u + static_cast<std::size_t>(description) + 120u * 12 * 3 * 2);
    CHECK(s.find("class A NTM, seed -5") != std::string::npos);
    CHECK(out.str().find("hub sigma u, v, w") != std::string::npos);
    CHECK(err.str().find("100 %") != std::string::npos);
    // The same options and seed: the same bytes.
    std::ostringstream out2, err2;
    CHECK(analysis::turbulence(small_options(dir + "/b.bts"), out2, err2) == 0);
    CHECK(test_support::read_file(dir + "/b.bts") == s);
}

TEST_CASE("turbulence refuses -o naming its input, and leaves no file when it fails") {
    const std::string dir = test_support::scratch_dir("turbulence", "refusals");
    const std::string input = dir + "/case.inp";
    const std::string text = test_support::read_file(std::string(YAMSC_TEST_DATA_DIR) +
                                                     "/reference/turbulence/U18_s1.inp");
    test_support::write_file(input, text);
    driver::TurbulenceOptions o;
    o.input = input;
    o.output = input;
    std::ostringstream out, err;
    CHECK_THROWS_AS(analysis::turbulence(o, out, err), diag::UsageError);
    CHECK(test_support::read_file(input) == text);

    // A grid reaching below the ground: a user error, nothing written.
    o.output = dir + "/out.bts";
    o.height = 400;
    CHECK_THROWS_AS(analysis::turbulence(o, out, err), diag::UserError);
    CHECK(!std::filesystem::exists(o.output));
    CHECK(std::distance(std::filesystem::directory_iterator(dir), {}) == 1);

    // Without a file the required options are asked for.
    driver::TurbulenceOptions none;
    none.output = o.output;
    CHECK_THROWS_AS(analysis::turbulence(none, out, err), diag::UsageError);
}
