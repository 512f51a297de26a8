// The wave fields: Airy's closed forms, the linear free-surface, continuity and
// bottom conditions by finite differences, SeaState's draws, variance, periodicity,
// seeds, stretching and the tabulated points.
#include <yamsc/hydro/ranlux.hpp>
#include <yamsc/hydro/waves.hpp>

#include <doctest/doctest.h>

#include <cmath>

using namespace yamsc::runtime::hydro;

namespace {
constexpr double pi = 3.14159265358979323846;

bool near(double a, double b, double tol) {
    return std::abs(a - b) <= tol;
}

WaveSettings irregular(double depth = 320) {
    WaveSettings s;
    s.kind = WaveKind::irregular;
    s.water.depth = depth;
    s.height = 6;
    s.period = 10;
    s.t_max = 600;
    s.dt = 0.25;
    s.low_cutoff = 0.1;
    s.high_cutoff = 3;
    s.seed1 = 123456789;
    s.direction = 0.5;
    return s;
}

WaveSettings regular(double depth, double phase) {
    WaveSettings s;
    s.kind = WaveKind::regular;
    s.water.depth = depth;
    s.height = 4;
    s.period = 10; // 600 s / 10 s: on the grid
    s.t_max = 600;
    s.phase = phase;
    s.direction = pi / 6;
    return s;
}
} // namespace

TEST_CASE("Still water: no elevation, no flow") {
    const auto f = make_wave_field(WaveSettings{});
    CHECK(f->elevation(3, 1, 2) == 0);
    CHECK(f->flow(3, {0, 0, -10}).velocity[0] == 0);
    CHECK(f->components().empty());
    CHECK(f->water().depth == 320);
}

TEST_CASE("Regular waves: Airy's closed forms at finite depth") {
    const double h = 40, phase = 0.7, g = 9.80665, rho = 1025;
    const auto f = make_wave_field(regular(h, phase));
    const double w = 2 * pi / 10, k = wave_number(w, g, h), a = 2;
    CHECK(w * w == doctest::Approx(g * k * std::tanh(k * h)).epsilon(1e-13));
    REQUIRE(f->components().size() == 1);
    CHECK(f->components()[0].omega == doctest::Approx(w).epsilon(1e-14));
    const double c = std::cos(pi / 6), s = std::sin(pi / 6);
    for (double t : {0.0, 1.3, 7.7})
        for (double z : {0.0, -5.0, -25.0, -40.0}) {
            const double x = 12, y = -7;
            const double th = w * t - k * (x * c + y * s) + phase;
            CHECK(f->elevation(t, x, y) == doctest::Approx(a * std::cos(th)).epsilon(1e-12));
            const auto fl = f->flow(t, {x, y, z});
            const double uh = a * w * std::cosh(k * (z + h)) / std::sinh(k * h) * std::cos(th);
            const double wz = -a * w * std::sinh(k * (z + h)) / std::sinh(k * h) * std::sin(th);
            const double ah = -a * w * w * std::cosh(k * (z + h)) / std::sinh(k * h) * std::sin(th);
            const double az = -a * w * w * std::sinh(k * (z + h)) / std::sinh(k * h) * std::cos(th);
            const double pd =
                rho * g * a * std::cosh(k * (z + h)) / std::cosh(k * h) * std::cos(th);
            CHECK(fl.velocity[0] == doctest::Approx(uh * c).epsilon(1e-11).scale(1e-12));
            CHECK(fl.velocity[1] == doctest::Approx(uh * s).epsilon(1e-11).scale(1e-12));
            CHECK(fl.velocity[2] == doctest::Approx(wz).epsilon(1e-11).scale(1e-12));
            CHECK(fl.acceleration[0] == doctest::Approx(ah * c).epsilon(1e-11).scale(1e-12));
            CHECK(fl.acceleration[2] == doctest::Approx(az).epsilon(1e-11).scale(1e-12));
            CHECK(fl.dynamic_pressure == doctest::Approx(pd).epsilon(1e-11).scale(1e-8));
        }
    // No stretching: nothing above the still-water level, nothing below the seabed.
    CHECK(f->flow(0, {0, 0, 0.5}).velocity[0] == 0);
    CHECK(f->flow(0, {0, 0, -40.5}).velocity[0] == 0);
}

TEST_CASE("Regular waves: the random phase is the RANLUX draw of the wave's frequency") {
    auto s = regular(320, 0);
    s.phase.reset();
    s.seed1 = -4321; // SeaState seeds with |WaveSeed(1)|
    const auto f = make_wave_field(s);
    // m = 60 (600 s / 10 s) takes draws 2 (m - 1) and 2 (m - 1) + 1 (m = 1 is skipped).
    Ranlux r(3, 4321);
    double u2 = 0;
    for (int i = 0; i <= 2 * 59 + 1; ++i) u2 = r.next();
    CHECK(std::arg(f->components()[0].amplitude) ==
          doctest::Approx(std::remainder(2 * pi * u2, 2 * pi)).epsilon(1e-12));
    CHECK(std::abs(f->components()[0].amplitude) == doctest::Approx(2).epsilon(1e-14));
}

TEST_CASE("Irregular waves: SeaState's amplitudes W sqrt(S dw) from its draws") {
    const auto s = irregular();
    const int n = wave_time_steps(s.t_max, s.dt);
    const auto a = sea_state_amplitudes(s, n);
    const double dw = 2 * pi / (n * s.dt);
    CHECK(a[1] == 0.0);                                              // SeaState skips m = 1
    CHECK(a[static_cast<std::size_t>(n / 2)] == 0.0);                // and the Nyquist frequency
    CHECK(a[static_cast<std::size_t>(std::floor(0.1 / dw))] == 0.0); // below the cut-off
    Ranlux r(3, 123456789);
    std::vector<double> u;
    for (int i = 0; i < 2 * 80; ++i) u.push_back(r.next());
    const double gamma = default_peak_shape(6, 10);
    for (int m : {40, 60, 79}) {
        const double u1 = u[static_cast<std::size_t>(2 * (m - 1))];
        const double u2 = u[static_cast<std::size_t>(2 * (m - 1) + 1)];
        const auto expected = std::polar(std::sqrt(-2 * std::log(u1)), 2 * pi * u2) *
                              std::sqrt(jonswap(m * dw, 6, 10, gamma) * dw);
        CAPTURE(m);
        CHECK(a[static_cast<std::size_t>(m)].real() ==
              doctest::Approx(expected.real()).epsilon(1e-12));
        CHECK(a[static_cast<std::size_t>(m)].imag() ==
              doctest::Approx(expected.imag()).epsilon(1e-12));
    }
}

TEST_CASE("Irregular waves: the realization's variance") {
    auto s = irregular();
    // Constant amplitudes: the variance over a period is the grid's m0 = sum S dw.
    s.normal_amplitudes = false;
    const auto f = make_wave_field(s);
    const double T = f->period(), dt = f->time_step();
    const int n = static_cast<int>(std::lround(T / dt));
    double var = 0, mean = 0;
    for (int j = 0; j < n; ++j) {
        const double e = f->elevation(j * dt, 3, 4);
        var += e * e / n;
        mean += e / n;
    }
    double m0 = 0;
    const double dw = 2 * pi / T, gamma = default_peak_shape(6, 10);
    for (int m = 2; m < n / 2; ++m)
        if (m * dw >= 0.1 && m * dw <= 3) m0 += jonswap(m * dw, 6, 10, gamma) * dw;
    CHECK(std::abs(mean) < 1e-12);
    CHECK(var == doctest::Approx(m0).epsilon(1e-10));
    CHECK(m0 == doctest::Approx(36.0 / 16).epsilon(0.01)); // the spectrum's m0 (test_spectrum)
    // Normally distributed amplitudes: Parseval holds for the realization, and its
    // variance is m0 within the sampling scatter of the components.
    s.normal_amplitudes = true;
    const auto g = make_wave_field(s);
    double var_n = 0, parseval = 0;
    for (int j = 0; j < n; ++j) var_n += std::pow(g->elevation(j * dt, 3, 4), 2) / n;
    for (const auto& c : g->components()) parseval += std::norm(c.amplitude) / 2;
    CHECK(var_n == doctest::Approx(parseval).epsilon(1e-10));
    // Each |W|^2 is exponential with mean 2: the variance's relative standard deviation
    // is sqrt(sum S^2) / sum S over the grid's components.
    double s1 = 0, s2 = 0;
    for (int m = 2; m < n / 2; ++m)
        if (m * dw >= 0.1 && m * dw <= 3) {
            const double sm = jonswap(m * dw, 6, 10, gamma);
            s1 += sm, s2 += sm * sm;
        }
    const double sd = std::sqrt(s2) / s1;
    MESSAGE("normal amplitudes: variance / m0 - 1 = " << var_n / m0 - 1 << ", sd " << sd);
    CHECK(std::abs(var_n / m0 - 1) < 3 * sd);
}

TEST_CASE("Irregular waves: same seed, same sea; another seed, another sea; period WaveTMax") {
    const auto a = make_wave_field(irregular());
    const auto b = make_wave_field(irregular());
    auto s = irregular();
    s.seed1 = 987654321;
    const auto c = make_wave_field(s);
    for (double t : {0.0, 12.3, 345.6}) {
        CHECK(a->elevation(t, 5, 6) == b->elevation(t, 5, 6));
        CHECK(a->elevation(t, 5, 6) != c->elevation(t, 5, 6));
        CHECK(near(a->elevation(t + a->period(), 5, 6), a->elevation(t, 5, 6), 1e-9));
        CHECK(near(a->flow(t + 3 * a->period(), {5, 6, -8}).velocity[2],
                   a->flow(t, {5, 6, -8}).velocity[2], 1e-9));
    }
    // The intrinsic generator's seeds give a realization of their own, reproducibly.
    s.ranlux = false;
    s.seed2 = 7;
    CHECK(make_wave_field(s)->elevation(1, 0, 0) == make_wave_field(s)->elevation(1, 0, 0));
}

TEST_CASE("Linear conditions by finite differences: surface, continuity, seabed, d/dt") {
    const double h = 60, g = 9.80665, rho = 1025;
    const auto f = make_wave_field(irregular(h));
    const double t = 37.2, x = 4, y = -3, e = 1e-4;
    // Kinematic surface condition: d(eta)/dt = w at z = 0.
    const double deta = (f->elevation(t + e, x, y) - f->elevation(t - e, x, y)) / (2 * e);
    CHECK(f->flow(t, {x, y, 0}).velocity[2] == doctest::Approx(deta).epsilon(1e-6));
    // Dynamic surface condition (linear Bernoulli): p_dyn = rho g eta at z = 0.
    CHECK(f->flow(t, {x, y, 0}).dynamic_pressure ==
          doctest::Approx(rho * g * f->elevation(t, x, y)).epsilon(1e-12));
    for (double z : {-1.0, -10.0, -45.0}) {
        CAPTURE(z);
        auto v = [&](double dx, double dy, double dz, int i) {
            return f->flow(t, {x + dx, y + dy, z + dz}).velocity[static_cast<std::size_t>(i)];
        };
        const double d = 1e-3;
        const double div = (v(d, 0, 0, 0) - v(-d, 0, 0, 0) + v(0, d, 0, 1) - v(0, -d, 0, 1) +
                            v(0, 0, d, 2) - v(0, 0, -d, 2)) /
                           (2 * d);
        const double scale = std::abs((v(d, 0, 0, 0) - v(-d, 0, 0, 0)) / (2 * d));
        CHECK(std::abs(div) < 1e-6 * scale);
        // The acceleration is the local time derivative of the velocity (linear theory).
        for (int i = 0; i < 3; ++i) {
            const double dv = (f->flow(t + e, {x, y, z}).velocity[static_cast<std::size_t>(i)] -
                               f->flow(t - e, {x, y, z}).velocity[static_cast<std::size_t>(i)]) /
                              (2 * e);
            CHECK(f->flow(t, {x, y, z}).acceleration[static_cast<std::size_t>(i)] ==
                  doctest::Approx(dv).epsilon(1e-6).scale(1e-8));
        }
    }
    // Seabed: no vertical velocity at z = -h.
    CHECK(near(f->flow(t, {x, y, -h}).velocity[2], 0, 1e-14));
}

TEST_CASE("Stretching: Wheeler, vertical, extrapolation against the unstretched field") {
    auto s = irregular(80);
    const auto plain = make_wave_field(s);
    s.stretching = Stretching::wheeler;
    const auto wheeler = make_wave_field(s);
    s.stretching = Stretching::vertical;
    const auto vertical = make_wave_field(s);
    s.stretching = Stretching::extrapolation;
    const auto extrap = make_wave_field(s);
    // A crest and a trough of the realization at x = y = 0.
    double t_crest = 0, t_trough = 0;
    for (double t = 0; t < 600; t += 0.05) {
        if (plain->elevation(t, 0, 0) > plain->elevation(t_crest, 0, 0)) t_crest = t;
        if (plain->elevation(t, 0, 0) < plain->elevation(t_trough, 0, 0)) t_trough = t;
    }
    const double eta = plain->elevation(t_crest, 0, 0);
    REQUIRE(eta > 1);
    // Wheeler: the surface takes the SWL's kinematics, the seabed its own, above is dry.
    CHECK(wheeler->flow(t_crest, {0, 0, eta}).velocity[0] ==
          doctest::Approx(plain->flow(t_crest, {0, 0, 0}).velocity[0]).epsilon(1e-12));
    CHECK(wheeler->flow(t_crest, {0, 0, -80}).velocity[0] ==
          doctest::Approx(plain->flow(t_crest, {0, 0, -80}).velocity[0]).epsilon(1e-12));
    const double zs = 80 * (-20 - eta) / (80 + eta);
    CHECK(wheeler->flow(t_crest, {0, 0, -20}).velocity[0] ==
          doctest::Approx(plain->flow(t_crest, {0, 0, zs}).velocity[0]).epsilon(1e-12));
    CHECK(wheeler->flow(t_crest, {0, 0, eta + 0.01}).velocity[0] == 0);
    // Vertical: above SWL the SWL's values up to the surface.
    CHECK(vertical->flow(t_crest, {0, 0, eta / 2}).velocity[0] ==
          plain->flow(t_crest, {0, 0, 0}).velocity[0]);
    CHECK(vertical->flow(t_crest, {0, 0, -3}).velocity[0] ==
          plain->flow(t_crest, {0, 0, -3}).velocity[0]);
    // Extrapolation: the SWL's value plus z times its z-derivative (central difference).
    const double dz = 1e-4;
    const double slope = (plain->flow(t_crest, {0, 0, 0}).velocity[0] -
                          plain->flow(t_crest, {0, 0, -2 * dz}).velocity[0]) /
                         (2 * dz);
    CHECK(extrap->flow(t_crest, {0, 0, eta / 2}).velocity[0] ==
          doctest::Approx(plain->flow(t_crest, {0, 0, 0}).velocity[0] + eta / 2 * slope)
              .epsilon(1e-6));
    // In a trough every stretched field is dry between the surface and the SWL.
    const double low = plain->elevation(t_trough, 0, 0);
    REQUIRE(low < -1);
    CHECK(vertical->flow(t_trough, {0, 0, low / 2}).velocity[0] == 0);
    CHECK(wheeler->flow(t_trough, {0, 0, low / 2}).velocity[0] == 0);
    CHECK(plain->flow(t_trough, {0, 0, low / 2}).velocity[0] != 0);
}

TEST_CASE("Tabulated points: exact on SeaState's time grid, its cubic in between") {
    for (auto st :
         {Stretching::none, Stretching::vertical, Stretching::extrapolation, Stretching::wheeler}) {
        auto s = irregular(100);
        s.stretching = st;
        const auto f = make_wave_field(s);
        for (Vec3 p : {Vec3{3, -2, -12}, Vec3{3, -2, 0.5}, Vec3{0, 0, -100.5}}) {
            const auto pt = f->at(p);
            const double dt = f->time_step();
            for (int j : {0, 1, 17, 2399}) {
                const double t = j * dt;
                CHECK(near(pt->elevation(t), f->elevation(t, p[0], p[1]), 1e-9));
                for (int i = 0; i < 3; ++i) {
                    const auto q = static_cast<std::size_t>(i);
                    CHECK(near(pt->flow(t).velocity[q], f->flow(t, p).velocity[q], 1e-9));
                    CHECK(near(pt->flow(t).acceleration[q], f->flow(t, p).acceleration[q], 1e-9));
                }
                CHECK(near(pt->flow(t).dynamic_pressure, f->flow(t, p).dynamic_pressure, 1e-6));
            }
            if (st == Stretching::wheeler) continue; // evaluated exactly, not tabulated
            // Between samples: the Catmull-Rom cubic through t = 16, 17, 18, 19 dt (SeaState's
            // GridInterp on its periodic time axis), also across the period's end.
            auto eta = [&](int j) { return f->elevation(j * dt, p[0], p[1]); };
            const double s = 0.3, s2 = s * s, s3 = s2 * s;
            const double cubic =
                (-0.5 * s3 + s2 - 0.5 * s) * eta(16) + (1.5 * s3 - 2.5 * s2 + 1) * eta(17) +
                (-1.5 * s3 + 2 * s2 + 0.5 * s) * eta(18) + (0.5 * s3 - 0.5 * s2) * eta(19);
            CHECK(near(pt->elevation((17 + s) * dt + f->period()), cubic, 1e-9));
            const double wrap =
                (-0.5 * s3 + s2 - 0.5 * s) * eta(-1) + (1.5 * s3 - 2.5 * s2 + 1) * eta(0) +
                (-1.5 * s3 + 2 * s2 + 0.5 * s) * eta(1) + (0.5 * s3 - 0.5 * s2) * eta(2);
            CHECK(near(pt->elevation(s * dt), wrap, 1e-9));
            // The interpolation error against the exact field, for the record.
            if (st == Stretching::none && p[2] < 0)
                MESSAGE("tabulated vs exact between samples: "
                        << pt->elevation((17 + s) * dt) - f->elevation((17 + s) * dt, p[0], p[1]));
        }
    }
}

TEST_CASE("Bad settings are refused as SeaState refuses them") {
    auto s = regular(320, 0);
    s.period = 700; // beyond WaveTMax / 2
    CHECK_THROWS_AS(make_wave_field(s), std::invalid_argument);
    auto t = irregular();
    t.peak_shape = 8;
    CHECK_THROWS_AS(make_wave_field(t), std::invalid_argument);
    t = irregular();
    t.dt = 0;
    CHECK_THROWS_AS(make_wave_field(t), std::invalid_argument);
}
