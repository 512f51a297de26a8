// The unsteady airfoil models against closed forms on a hand-built airfoil whose lift
// follows Kirchhoff's flat plate, Cl = Cl_alpha (alpha - alpha0) ((1 + sqrt f)/2)^2,
// with a known separation function f(alpha).
#include "yamsc/aero/unsteady_airfoil.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace yamsc::aero;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi / 180;
constexpr double alpha0 = -2 * deg, slope = 2 * pi, cd0 = 0.01;

// 1 within 8 deg of alpha0, falling to 0 at 25 deg from it.
double f_of(double alpha) {
    const double x = (std::abs(alpha - alpha0) - 8 * deg) / (17 * deg);
    return x <= 0 ? 1.0 : std::pow(std::max(0.0, 1 - x), 2);
}

Airfoil kirchhoff() {
    PolarTable t;
    for (int a = -180; a <= 180; ++a) {
        const double alpha = a * deg, f = f_of(alpha);
        t.alpha.push_back(alpha);
        t.cl.push_back(slope * (alpha - alpha0) * std::pow((1 + std::sqrt(f)) / 2, 2));
        t.cd.push_back(cd0 + 0.5 * (1 - f) * std::abs(std::sin(alpha)));
        t.cm.push_back(-0.05 - 0.1 * (1 - f));
    }
    UnsteadyConstants k;
    k.alpha0 = alpha0;
    k.C_nalpha = slope;
    k.C_lalpha = slope;
    k.Cd0 = cd0;
    k.Cn1 = 1.9; // leading-edge separation far beyond the angles used here
    k.Cn2 = -1.9;
    k.alphaUpper = alpha0 + 8 * deg;
    k.alphaLower = alpha0 - 8 * deg;
    t.unsteady = k;
    Airfoil af;
    af.name = "kirchhoff";
    af.tables.push_back(t);
    return af;
}

UnsteadyInput steady_input(double alpha, double U) {
    UnsteadyInput u;
    u.U = U;
    u.alpha = alpha;
    u.v_ac_n = U * std::sin(alpha);
    u.v_ac_c = U * std::cos(alpha);
    return u;
}

constexpr double chord = 2, speed = 40;

} // namespace

TEST_CASE("Oye's separation function recovers Kirchhoff's f from the polar") {
    const UnsteadyAirfoil af(kirchhoff());
    CHECK(af.supports(UnsteadyModel::oye));
    CHECK(af.supports(UnsteadyModel::minnema_pierce));
    for (int a = -20; a <= 30; ++a) {
        const double alpha = a * deg;
        const auto p = af.at(alpha);
        CHECK(p.f_st == doctest::Approx(f_of(alpha)).epsilon(1e-9));
        // Cl = f Cl_attached + (1 - f) Cl_separated at every table angle.
        CHECK(p.f_st * slope * (alpha - alpha0) + (1 - p.f_st) * p.cl_fs ==
              doctest::Approx(p.cl).epsilon(1e-9));
    }
}

TEST_CASE("Oye: x4 lags f_st with the time constant T_f0 c / (2 U)") {
    const UnsteadyAirfoil af(kirchhoff());
    const double alpha = 16 * deg, f = f_of(alpha);
    const double T = af.constants().T_f0 * chord / (2 * speed);
    const UnsteadyInput u = steady_input(alpha, speed);
    for (auto integrator : {UnsteadyIntegrator::rk4, UnsteadyIntegrator::abm4}) {
        UnsteadySettings s;
        s.model = UnsteadyModel::oye;
        s.integrator = integrator;
        OyeState x;
        x.first_pass = false;
        x.x4 = 1; // attached flow suddenly at 16 deg
        CHECK(oye_derivative(af, s, chord, u, 1.0) == doctest::Approx((f - 1) / T));
        const double dt = 0.002;
        for (int n = 0; n < 50; ++n) step(af, s, chord, dt, u, u, x);
        const double expected = f + (1 - f) * std::exp(-50 * dt / T);
        CHECK(x.x4 == doctest::Approx(expected).epsilon(1e-6));
        // Outputs mix attached and separated lift by x4.
        const UnsteadyOutput y = evaluate(af, s, chord, u, x);
        const auto p = af.at(alpha);
        CHECK(y.cl == doctest::Approx(x.x4 * slope * (alpha - alpha0) + (1 - x.x4) * p.cl_fs));
        CHECK(y.cd == doctest::Approx(p.cd));
    }
}

TEST_CASE("UA_Mod 3 at a constant angle of attack settles on the steady polar") {
    const UnsteadyAirfoil af(kirchhoff());
    UnsteadySettings s;
    for (double a : {3.0, 9.5, 13.0}) { // attached, f just below 1, partly separated
        const double alpha = a * deg;
        MinnemaPierceState x;
        UnsteadyOutput y;
        for (int n = 0; n < 4000; ++n) y = step(af, s, chord, 0.005, steady_input(alpha, speed), x);
        const auto p = af.at(alpha);
        CAPTURE(a);
        // f'' solves Cn = C_nalpha / beta (alpha - alpha0) ((1 + sqrt f)/2)^2 at the polar's
        // Cn = Cl cos + (Cd - Cd0) sin, beta = sqrt(1 - M^2) (Prandtl-Glauert).
        const double beta = std::sqrt(1 - std::pow(speed / s.speed_of_sound, 2));
        const double cn = p.cl * std::cos(alpha) + (p.cd - cd0) * std::sin(alpha);
        const double f = std::pow(2 * std::sqrt(cn / (slope / beta * (alpha - alpha0))) - 1, 2);
        CHECK(y.fprimeprime == doctest::Approx(f).epsilon(1e-6));
        CHECK(y.cl == doctest::Approx(p.cl).epsilon(1e-6));
        CHECK(y.cd == doctest::Approx(p.cd).epsilon(1e-6));
        CHECK(y.cm == doctest::Approx(p.cm).epsilon(1e-6));
    }
}

TEST_CASE("UA_Mod 3: slow small pitching in attached flow tends to the steady polar") {
    const UnsteadyAirfoil af(kirchhoff());
    UnsteadySettings s;
    // 3 +- 0.5 deg; reduced frequency k = omega c / (2 U).
    auto worst = [&](double k) {
        const double w = 2 * k * speed / chord, dt = 0.01;
        const int steps = static_cast<int>(2 * 2 * pi / w / dt);
        MinnemaPierceState x;
        double e = 0;
        for (int n = 0; n < steps; ++n) {
            const double t = n * dt, alpha = (3 + 0.5 * std::sin(w * t)) * deg;
            UnsteadyInput u = steady_input(alpha, speed);
            u.omega = 0.5 * deg * w * std::cos(w * t);
            const UnsteadyOutput y = step(af, s, chord, dt, u, x);
            if (n > steps / 2) e = std::max(e, std::abs(y.cl - af.at(alpha).cl));
        }
        return e / (slope * 1 * deg); // relative to the steady Cl swing
    };
    const double slow = worst(0.002), faster = worst(0.02);
    MESSAGE("UA_Mod 3 Cl off the steady polar / steady swing: k=0.002 " << slow << ", k=0.02 "
                                                                        << faster);
    CHECK(slow < 0.02);
    CHECK(slow < faster);
}

TEST_CASE("Unsteady aerodynamics is off where AeroDyn turns it off") {
    Airfoil no_ua = kirchhoff();
    no_ua.tables.front().unsteady.reset();
    CHECK_FALSE(UnsteadyAirfoil(no_ua).supports(UnsteadyModel::minnema_pierce));
    Airfoil flat = kirchhoff();
    auto& t = flat.tables.front();
    std::fill(t.cl.begin(), t.cl.end(), 0.3);
    std::fill(t.cd.begin(), t.cd.end(), 0.02);
    CHECK_FALSE(UnsteadyAirfoil(flat).supports(UnsteadyModel::oye));
    Airfoil no_slope = kirchhoff();
    no_slope.tables.front().unsteady->C_lalpha = 0;
    CHECK_FALSE(UnsteadyAirfoil(no_slope).supports(UnsteadyModel::oye));
    CHECK(UnsteadyAirfoil(no_slope).supports(UnsteadyModel::minnema_pierce));
}

TEST_CASE("Unsteady settings from the AeroDyn primary file's switches") {
    RotorInput rotor;
    rotor.unsteady = UnsteadyModel::oye;
    rotor.speed_of_sound = 340;
    const UnsteadySettings s = unsteady_settings(rotor);
    CHECK(s.model == UnsteadyModel::oye);
    CHECK(s.speed_of_sound == 340);
    CHECK(s.integrator == UnsteadyIntegrator::abm4);
}
