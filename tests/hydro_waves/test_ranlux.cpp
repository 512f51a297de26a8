// RANLUX against the test values F. James published with the algorithm (Comput.
// Phys. Commun. 79 (1994) 111, the output of its test program, 8 digits).
#include <yamsc/hydro/ranlux.hpp>

#include <doctest/doctest.h>

#include <array>
#include <stdexcept>
#include <vector>

using yamsc::runtime::hydro::Ranlux;

namespace {
std::vector<double> draw(Ranlux& r, int n) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.push_back(r.next());
    return v;
}
void check(const std::vector<double>& v, int first, const std::array<double, 5>& expected) {
    for (int i = 0; i < 5; ++i)
        CHECK(v[static_cast<std::size_t>(first - 1 + i)] ==
              doctest::Approx(expected[static_cast<std::size_t>(i)]).epsilon(1e-7));
}
} // namespace

TEST_CASE("RANLUX: the default seed at the default luxury level 3 (p = 223)") {
    Ranlux r; // 314159265, level 3
    const auto v = draw(r, 105);
    check(v, 1, {0.53981817, 0.76155043, 0.06029940, 0.79600263, 0.30631220});
    check(v, 101, {0.43156743, 0.03774416, 0.24897110, 0.00147784, 0.90274453});
}

TEST_CASE("RANLUX: luxury level 0 (p = 24) differs after the first block") {
    Ranlux r(0, 0);
    const auto v = draw(r, 105);
    check(v, 1, {0.53981817, 0.76155043, 0.06029940, 0.79600263, 0.30631220});
    check(v, 101, {0.41538775, 0.05330932, 0.58195311, 0.91397446, 0.67034441});
}

TEST_CASE("RANLUX: seed 1 at luxury level 4 (p = 389)") {
    Ranlux r(4, 1);
    const auto v = draw(r, 105);
    check(v, 1, {0.94589490, 0.47347850, 0.95152789, 0.42971975, 0.09127384});
    check(v, 101, {0.02618265, 0.03775346, 0.97274780, 0.13302165, 0.43126065});
}

TEST_CASE("RANLUX: numbers lie in (0, 1); bad levels and seeds are refused") {
    Ranlux r(3, 123456);
    for (double x : draw(r, 20000)) {
        CHECK(x > 0);
        CHECK(x < 1);
    }
    CHECK_THROWS_AS(Ranlux(5, 1), std::invalid_argument);
    CHECK_THROWS_AS(Ranlux(3, -1), std::invalid_argument);
}
