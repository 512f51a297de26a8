// --real on the command line, float literals and the C syntax of float, and a
// constant a float cannot hold.
#include "codegen/syntax.hpp"
#include "embedded/support.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <limits>

using namespace embedded_test;
using namespace yamsc::codegen;

namespace {

// The exit status of yamsc with `args`; its stderr in `err`.
int run_yamsc(const std::string& dir, const std::string& args, std::string& err) {
    const int status =
        run(std::string(YAMSC_EXE) + " " + args + " > /dev/null 2> " + dir + "/err.txt");
    err = read_file(dir + "/err.txt");
    return status;
}

const std::string pendulum = std::string(YAMSC_SOURCE_DIR) + "/models/pendulum.mbd";

} // namespace

TEST_CASE("--real float is for C only, and --real takes double or float") {
    const std::string dir = scratch_dir("cli");
    std::string err;
    CHECK(run_yamsc(dir, pendulum + " -o " + dir + "/p.cpp --real float", err) == 2);
    CHECK(err.find("--real float applies to --lang c only") != std::string::npos);
    CHECK(run_yamsc(dir, pendulum + " -o " + dir + "/p.c --lang cpp --real float", err) == 2);
    CHECK(run_yamsc(dir, pendulum + " -o " + dir + "/p.c --real bogus", err) == 2);
    CHECK(err.find("--real must be double or float, not 'bogus'") != std::string::npos);
    CHECK(run_yamsc(dir, pendulum + " -o " + dir + "/p.cpp --real double", err) == 0);
    REQUIRE(run_yamsc(dir, pendulum + " -o " + dir + "/p.c --real float", err) == 0);
    const std::string c = read_file(dir + "/p.c");
    CHECK(c.find("typedef float pendulum_real;") != std::string::npos);
    CHECK(c.find("p.g = 9.81f;") != std::string::npos);
    CHECK(c.find("sinf(") != std::string::npos);
    CHECK(c.find("double") == std::string::npos);
    CHECK(c.find("// Code: C in single precision (float), prefix pendulum") != std::string::npos);
}

TEST_CASE("a constant beyond the float range is an error with --real float, fine in double") {
    const std::string dir = scratch_dir("range");
    write_file(dir + "/big.mbd", "model big\n"
                                 "param m = 1.0\nparam g = 1e300\n"
                                 "dof x\n"
                                 "gravity (0, 0, -g)\n"
                                 "rigid b { mass = m }\n"
                                 "joint ground -> b { translate z x }\n");
    std::string err;
    REQUIRE_MESSAGE(run_yamsc(dir, dir + "/big.mbd -o " + dir + "/big.c", err) == 0, err);
    CHECK(run_yamsc(dir, dir + "/big.mbd -o " + dir + "/bigf.c --real float", err) == 1);
    CHECK_MESSAGE(err.find("'g'") != std::string::npos, err);
    CHECK_MESSAGE(err.find("1e+300 does not fit in a float") != std::string::npos, err);
    CHECK(err.find("internal error") == std::string::npos);
}

TEST_CASE("float literals: the nearest float, shortest, with an f") {
    CHECK(format_float(9.81) == "9.81f");
    CHECK(format_float(1.0) == "1.0f");
    CHECK(format_float(-2.5) == "-2.5f");
    CHECK(format_float(0.0) == "0.0f");
    CHECK(format_float(1.0 / 3.0) == "0.33333334f");
    CHECK(format_float(1e-5) == "1e-05f");
    CHECK(format_float(1e20) == "1e+20f");
    CHECK(format_float(16777217.0) == "16777216.0f"); // 2^24 + 1 has no float
    CHECK(std::strtof(format_float(0.1 + 0.2).c_str(), nullptr) == static_cast<float>(0.1 + 0.2));
    CHECK(format_float(3.4e38) == "3.4e+38f");
    CHECK_THROWS_AS(format_float(1e300), NumberOutOfRange);
    CHECK_THROWS_AS(format_float(-4e38), NumberOutOfRange);
    CHECK_THROWS_AS(format_float(std::numeric_limits<double>::infinity()), NumberOutOfRange);
    // Below the smallest float: a signed zero (round-off constants of the data).
    CHECK(format_float(4e-54) == "0.0f");
    CHECK(format_float(-4e-54) == "-0.0f");
    CHECK(format_float(1e-40) == "1e-40f"); // subnormal, still nonzero
    // Double syntax is unchanged; the float one spells functions the C99 float way.
    CHECK(format_literal(9.81, c_syntax("m")) == "9.81");
    CHECK(format_literal(9.81, c_syntax("m", true)) == "9.81f");
    const Syntax f = c_syntax("m", true);
    CHECK(f.functions[static_cast<int>(Function::abs)] == "fabsf");
    CHECK(f.functions[static_cast<int>(Function::atan2)] == "atan2f");
    CHECK(f.real_type == "float");
    CHECK(c_syntax("m").real_type == "double");
}
