// The shortest decimal of a double (text/number.hpp): it reads back exactly,
// and each layout is the text its users wrote before they shared it (fmt's
// "{}", printf's %g with the smallest precision that reads back, to_chars).
#include "text/number.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

using yamsc::text::shortest;
using yamsc::text::shortest_general;
using yamsc::text::shortest_printf;

namespace {

/// printf's %.Pg for the first P from `from` that reads back (what JSON and
/// the Campbell CSV wrote).
std::string printf_loop(double v, int from) {
    char buffer[40];
    for (int p = from; p <= 17; ++p) {
        std::snprintf(buffer, sizeof buffer, "%.*g", p, v);
        if (std::strtod(buffer, nullptr) == v) break;
    }
    return buffer;
}

std::string to_chars_text(double v) {
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, v);
    REQUIRE(error == std::errc());
    return std::string(buffer, end);
}

/// Doubles of every binade (random bit patterns) and the decimals data files
/// hold (short mantissas at every scale), integers near 2^53 and 1e16, and
/// their negatives.
std::vector<double> sample() {
    std::mt19937_64 random(24);
    std::vector<double> values;
    for (int i = 0; i < 30000; ++i) {
        const std::uint64_t bits = random();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        if (std::isfinite(v)) values.push_back(v);
    }
    std::uniform_int_distribution<int> digits(1, 17), scale(-30, 30);
    for (int i = 0; i < 30000; ++i) {
        const int n = digits(random);
        const long long mantissa =
            static_cast<long long>(random() % static_cast<std::uint64_t>(std::pow(10.0, n)));
        values.push_back(static_cast<double>(mantissa) * std::pow(10.0, scale(random)));
    }
    for (int i = -2000; i <= 2000; ++i) {
        values.push_back(9007199254740992.0 + 2.0 * i);
        values.push_back(1e16 + 2.0 * i);
        values.push_back(1e17 + 16.0 * i);
        values.push_back(i);
        values.push_back(i / 8.0);
    }
    const std::size_t n = values.size();
    for (std::size_t i = 0; i < n; ++i) values.push_back(-values[i]);
    return values;
}

} // namespace

TEST_CASE("shortest: every layout reads back as the same double") {
    for (double v : sample()) {
        for (const std::string& text :
             {shortest(v), shortest_general(v), shortest_printf(v, 6), shortest_printf(v, 15)}) {
            const double back = std::strtod(text.c_str(), nullptr);
            REQUIRE_MESSAGE(std::memcmp(&back, &v, sizeof v) == 0, text);
        }
    }
}

TEST_CASE("shortest: the same text as the writers it replaced") {
    std::size_t differ = 0;
    for (double v : sample()) {
        if (shortest(v) != to_chars_text(v) || shortest_general(v) != fmt::format("{}", v) ||
            shortest_printf(v, 15) != printf_loop(v, 15) ||
            shortest_printf(v, 6) != printf_loop(v, 6)) {
            if (++differ <= 10)
                MESSAGE(fmt::format("{}: {} {} {} {}", v, shortest(v), shortest_general(v),
                                    shortest_printf(v, 15), shortest_printf(v, 6)));
        }
    }
    CHECK(differ == 0);
    std::mt19937 random(7);
    for (int i = 0; i < 100000; ++i) {
        std::uint32_t bits = static_cast<std::uint32_t>(random());
        float f;
        std::memcpy(&f, &bits, sizeof f);
        if (!std::isfinite(f)) continue;
        REQUIRE(shortest_general(f) == fmt::format("{}", f));
        REQUIRE(std::strtof(shortest_general(f).c_str(), nullptr) == f);
    }
}

TEST_CASE("shortest: fixed cases of each layout") {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Case {
        double v;
        const char *to_chars, *general, *printf15, *printf6;
    };
    for (const Case& c : std::vector<Case>{
             {0.1, "0.1", "0.1", "0.1", "0.1"},
             {1, "1", "1", "1", "1"},
             {-0.0, "-0", "-0", "-0", "-0"},
             {100, "100", "100", "100", "100"},
             {1e6, "1e+06", "1000000", "1000000", "1e+06"},
             {1234567, "1234567", "1234567", "1234567", "1234567"},
             {1e15, "1e+15", "1000000000000000", "1e+15", "1e+15"},
             {1e16, "1e+16", "1e+16", "1e+16", "1e+16"},
             {0.0001, "1e-04", "0.0001", "0.0001", "0.0001"},
             {0.00001, "1e-05", "1e-05", "1e-05", "1e-05"},
             {0.00015, "0.00015", "0.00015", "0.00015", "0.00015"},
             {1.5e-7, "1.5e-07", "1.5e-07", "1.5e-07", "1.5e-07"},
             {1e-300, "1e-300", "1e-300", "1e-300", "1e-300"},
             {1.7976931348623157e308, "1.7976931348623157e+308", "1.7976931348623157e+308",
              "1.7976931348623157e+308", "1.7976931348623157e+308"},
             {5e-324, "5e-324", "5e-324", "4.94065645841247e-324", "4.94066e-324"},
             {0.30000000000000004, "0.30000000000000004", "0.30000000000000004",
              "0.30000000000000004", "0.30000000000000004"},
             {12345678901234568, "12345678901234568", "1.2345678901234568e+16", "12345678901234568",
              "12345678901234568"},
             {-2.5, "-2.5", "-2.5", "-2.5", "-2.5"},
             {inf, "inf", "inf", "inf", "inf"},
             {-inf, "-inf", "-inf", "-inf", "-inf"},
             {nan, "nan", "nan", "nan", "nan"},
         }) {
        CAPTURE(std::string(c.to_chars));
        CHECK(shortest(c.v) == c.to_chars);
        CHECK(shortest_general(c.v) == c.general);
        CHECK(shortest_printf(c.v, 15) == c.printf15);
        CHECK(shortest_printf(c.v, 6) == c.printf6);
    }
    CHECK(shortest_general(9.81f) == "9.81");
    CHECK(shortest_general(1e-45f) == "1e-45");
    CHECK(shortest_general(10.0, 1) == "1e+01");
    CHECK(shortest_general(0.5, 0) == "0.5");
}
