// Command-line values (`--set a=1,b'=5deg`, `--q 1,2`): what is accepted, what it
// means, and that everything else is a UsageError (exit 2) naming the option.
#include "driver/values.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using yamsc::diag::UsageError;
using yamsc::driver::parse_assignments;
using yamsc::driver::parse_list;
using yamsc::driver::parse_value;

TEST_CASE("values: numbers, degrees and blanks") {
    CHECK(parse_value("1.5", "--t") == 1.5);
    CHECK(parse_value(" -2e3 ", "--t") == -2000.0);
    CHECK(parse_value("180deg", "--t") == doctest::Approx(M_PI).epsilon(1e-15));
    CHECK(parse_value("90 deg", "--t") == doctest::Approx(M_PI / 2).epsilon(1e-15));
    CHECK(parse_value("1e-400", "--t") == 0.0); // underflow is zero, not an error
}

TEST_CASE("values: anything else is a usage error that names the option and the text") {
    for (const char* bad : {"", " ", "abc", "1.5x", "deg", "1e999", "-1e999", "nan", "inf", "1..2",
                            "5 degrees", "1,2"}) {
        CAPTURE(bad);
        try {
            parse_value(bad, "--tmax");
            FAIL("accepted");
        } catch (const UsageError& e) {
            CHECK(std::string(e.what()).find("--tmax") == 0);
            CHECK(std::string(e.what()).find(std::string("'") + bad + "'") != std::string::npos);
        }
    }
}

TEST_CASE("values: lists and assignments") {
    auto list = parse_list("1, 2.5 ,-3", "--q");
    REQUIRE(list.size() == 3);
    CHECK(list[1] == 2.5);
    CHECK(list[2] == -3.0);
    auto set = parse_assignments("theta_t=5deg, psi''=0.5 ,L=2", "--set");
    REQUIRE(set.size() == 3);
    CHECK(set[0].name == "theta_t");
    CHECK(set[0].value == doctest::Approx(5 * M_PI / 180).epsilon(1e-15));
    CHECK(set[1].name == "psi");
    CHECK(set[1].primes == 2);
    CHECK(set[2].value == 2.0);
    for (const char* bad : {"", "1,,2", "1,", ",1"})
        CHECK_THROWS_AS(parse_list(bad, "--q"), UsageError);
    for (const char* bad : {"", "a", "=1", "a=", "a=1,", "'=1", "''=1", "a=b", "a=1=2", "a=1,b"})
        CHECK_THROWS_AS(parse_assignments(bad, "--set"), UsageError);
}
