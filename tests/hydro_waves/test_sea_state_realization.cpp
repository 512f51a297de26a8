// The draws against SeaState's own output: OpenFAST's regression case
// modules/seastate/seastate_1 (r-test repository; numbers quoted from its
// seastate.SeaSt.out, 7 significant digits): white noise between 0.314159 and
// 1.570796 rad/s, Hs 1.7884 m, 600 s at 0.2 s, WaveSeed 123456789 with RANLUX,
// WaveNDAmp FALSE, depth 200 m, heading 0. SeaState evaluates its elevation on a
// 10 x 10 grid of half-width 30 m by cubic (Catmull-Rom) interpolation; the same
// interpolation of yamsc's exact values at those grid nodes gives its numbers.
#include <yamsc/hydro/ranlux.hpp>
#include <yamsc/hydro/waves.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <vector>

using namespace yamsc::runtime::hydro;

TEST_CASE("SeaState's realization: white noise of seed 123456789 (r-test seastate_1)") {
    const double pi = 3.14159265358979323846, dt = 0.2, hs = 1.7884, lo = 0.314159, hi = 1.570796,
                 h = 200, g = 9.80665;
    const int n = wave_time_steps(600, dt), n2 = n / 2;
    REQUIRE(n == 3000);
    const double dw = 2 * pi / (n * dt);
    // SeaState's draw order (as sea_state_amplitudes, whose draws test_field checks):
    // m = 0, 2, 3, ..., each U1 then U2; constant amplitudes sqrt(2); white noise S.
    Ranlux r(3, 123456789);
    std::vector<std::complex<double>> a(static_cast<std::size_t>(n2) + 1);
    for (int m = 0; m < n2; ++m) {
        if (m == 1) continue;
        double u1 = 0;
        while (u1 == 0) u1 = r.next();
        const double u2 = r.next();
        const double s = m * dw < lo || m * dw > hi ? 0 : hs * hs / (16 * (hi - lo));
        a[static_cast<std::size_t>(m)] =
            std::polar(std::sqrt(2.0), 2 * pi * u2) * std::sqrt(s * dw);
    }
    auto eta = [&](double t, double x) {
        double e = 0;
        for (int m = 2; m < n2; ++m)
            e += (a[static_cast<std::size_t>(m)] *
                  std::polar(1.0, m * dw * t - wave_number(m * dw, g, h) * x))
                     .real();
        return e;
    };
    // SeaState's grid: x_i = -30 + i 30/9; the Catmull-Rom cubic through four nodes.
    auto on_grid = [&](double t, double x) {
        const double dx = 30.0 / 9, p = (x + 30) / dx, i = std::floor(p), s = p - i;
        const double s2 = s * s, s3 = s2 * s;
        const double w[4] = {-0.5 * s3 + s2 - 0.5 * s, 1.5 * s3 - 2.5 * s2 + 1,
                             -1.5 * s3 + 2 * s2 + 0.5 * s, 0.5 * s3 - 0.5 * s2};
        double v = 0;
        for (int q = 0; q < 4; ++q) v += w[q] * eta(t, -30 + (i - 1 + q) * dx);
        return v;
    };
    // Wave1Elev at (14.43376, 25), Wave2Elev at (-18.47520, -6), at t = 0 and 0.2 s.
    CHECK(on_grid(0, 14.43376) == doctest::Approx(-0.2010358).epsilon(5e-7));
    CHECK(on_grid(0, -18.4752) == doctest::Approx(-0.3520891).epsilon(5e-7));
    CHECK(on_grid(0.2, 14.43376) == doctest::Approx(-0.1636420).epsilon(5e-7));
    CHECK(on_grid(0.2, -18.4752) == doctest::Approx(-0.4291466).epsilon(5e-7));
    // Exactly at the points the elevation differs by SeaState's grid error (declined).
    CHECK(std::abs(eta(0, 14.43376) / -0.2010358 - 1) > 1e-3);
}
