// AeroDyn's steady BEM of one element against closed forms: a thin plate
// (Cl = 2 pi alpha, Cd = 0) designed backwards from a chosen induction, Buhl's
// continuity at a = 0.4, Prandtl's factor, the propeller brake, the fixed tip
// induction, the Pitt/Peters redistribution, and a root in every case.
#include "yamsc/aero/bem.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace yamsc::aero;

namespace {

constexpr double pi = 3.14159265358979323846;

// Cl = 2 pi alpha over the whole circle: two rows, exact for linear lookup.
Airfoil thin_plate() {
    PolarTable t;
    t.alpha = {-pi, pi};
    t.cl = {-2 * pi * pi, 2 * pi * pi};
    t.cd = {0, 0};
    Airfoil a;
    a.name = "thin plate";
    a.tables.push_back(t);
    return a;
}

// A plate that stalls: lift capped at 1.2, drag growing with |alpha|, so the
// residual can have several roots.
Airfoil stalling_plate() {
    PolarTable t;
    for (int i = -36; i <= 36; ++i) {
        const double a = i * pi / 36;
        t.alpha.push_back(a);
        t.cl.push_back(std::clamp(2 * pi * a, -1.2, 1.2) * std::cos(a));
        t.cd.push_back(0.01 + 1.2 * std::sin(a) * std::sin(a));
    }
    Airfoil af;
    af.tables.push_back(t);
    return af;
}

ElementInput element(const Airfoil& af) {
    ElementInput in;
    in.vx = 10;
    in.vy = 60;
    in.r = 30;
    in.z = 30;
    in.z_hub = 1.5;
    in.z_tip = 63;
    in.blades = 3;
    in.chord = 2;
    in.airfoil = &af;
    return in;
}

BemOptions no_losses(bool tangential) {
    BemOptions o;
    o.tip_loss = o.hub_loss = false;
    o.tangential_induction = tangential;
    o.skew_redistribution = false;
    return o;
}

// The twist that makes a0 the momentum solution of the thin plate: with
// k = a/(1-a) = sigma Cl cos(phi) / (4 sin^2 phi) and, with tangential
// induction, kp = sigma Cl / (4 cos phi) = k tan^2 phi, tan phi follows from
// tan(phi) (1 + kp/(1-kp)) = (1-a) Vx/Vy in closed form.
struct Design {
    double theta, phi, ap;
};
Design design(const ElementInput& in, double a0, bool tangential) {
    const double sigma = in.blades * in.chord / (2 * pi * in.r);
    const double k = a0 / (1 - a0);
    const double c = (1 - a0) * in.vx / in.vy;
    const double t = tangential ? (-1 + std::sqrt(1 + 4 * k * c * c)) / (2 * k * c) : c;
    const double phi = std::atan(t);
    const double cl = 4 * std::sin(phi) * std::sin(phi) * k / (sigma * std::cos(phi));
    const double kp = tangential ? k * t * t : 0.0;
    return {phi - cl / (2 * pi), phi, kp / (1 - kp)};
}

} // namespace

TEST_CASE("bem: the thin plate's root is the momentum solution it was designed for") {
    const Airfoil af = thin_plate();
    for (const bool tangential : {false, true}) {
        for (const double a0 : {0.05, 0.2, 1.0 / 3.0, 0.38}) {
            CAPTURE(tangential);
            CAPTURE(a0);
            ElementInput in = element(af);
            const Design d = design(in, a0, tangential);
            in.theta = d.theta;
            const ElementSolution s = solve_element(in, no_losses(tangential), 1.225);
            CHECK(s.valid);
            CHECK(std::abs(s.phi - d.phi) < 2e-6);
            CHECK(std::abs(s.a - a0) < 2e-5);
            CHECK(std::abs(s.ap - d.ap) < 2e-6);
            CHECK(s.F == 1.0);
            // Loads from the coefficients: Cx = Cl cos phi, Cy = Cl sin phi.
            const double q = 0.5 * 1.225 * s.vrel * s.vrel * in.chord;
            CHECK(s.fx == doctest::Approx(2 * pi * s.alpha * std::cos(s.phi) * q).epsilon(1e-12));
            CHECK(s.fy == doctest::Approx(2 * pi * s.alpha * std::sin(s.phi) * q).epsilon(1e-12));
            CHECK(s.vrel == doctest::Approx(std::hypot(in.vx * (1 - s.a), in.vy * (1 + s.ap))));
        }
    }
}

TEST_CASE("bem: Buhl's correction continues the momentum induction at a = 0.4") {
    for (const double F : {1.0, 0.7, 0.3}) {
        CAPTURE(F);
        const double k0 = 2.0 / 3.0;
        CHECK(axial_induction_momentum(k0, F) == doctest::Approx(0.4).epsilon(1e-12));
        CHECK(axial_induction_momentum(k0 + 1e-9, F) == doctest::Approx(0.4).epsilon(1e-7));
        // Above: Buhl's thrust CT = 8/9 + (4F - 40/9) a + (50/9 - 4F) a^2 equals
        // the blade element's 4 F k (1 - a)^2.
        for (const double k : {0.8, 1.5, 4.0}) {
            const double a = axial_induction_momentum(k, F);
            CHECK(a > 0.4);
            const double ct = 8.0 / 9 + (4 * F - 40.0 / 9) * a + (50.0 / 9 - 4 * F) * a * a;
            CHECK(ct == doctest::Approx(4 * F * k * (1 - a) * (1 - a)).epsilon(1e-10));
        }
        CHECK(axial_induction_momentum(0.25, F) == doctest::Approx(0.2));
    }
}

TEST_CASE("bem: Prandtl's tip and hub factors") {
    const Airfoil af = thin_plate();
    ElementInput in = element(af);
    in.z = 50;
    const double phi = 0.2;
    BemOptions o;
    auto f = [&](double c) { return 2 / pi * std::acos(std::exp(-c / std::sin(phi))); };
    const double tip = f(3 * (63.0 - 50.0) / (2 * 50.0)), hub = f(3 * (50.0 - 1.5) / (2 * 1.5));
    o.hub_loss = false;
    CHECK(prandtl_loss(in, o, phi) == doctest::Approx(tip).epsilon(1e-14));
    CHECK(prandtl_loss(in, o, -phi) == doctest::Approx(tip).epsilon(1e-14)); // |sin phi|
    o.hub_loss = true;
    o.tip_loss = false;
    CHECK(prandtl_loss(in, o, phi) == doctest::Approx(hub).epsilon(1e-14));
    o.tip_loss = true;
    CHECK(prandtl_loss(in, o, phi) == doctest::Approx(tip * hub).epsilon(1e-14));
    CHECK(tip < 0.99);
    // The residual's inductions use it: k = sigma Cx / (4 F sin^2 phi).
    in.theta = 0.05;
    const Residual r = bem_residual(in, o, phi);
    const double sigma = 3 * 2.0 / (2 * pi * 30);
    const double cx = 2 * pi * (phi - 0.05) * std::cos(phi);
    CHECK(r.F == doctest::Approx(tip * hub).epsilon(1e-14));
    CHECK(r.k == doctest::Approx(sigma * cx / (4 * tip * hub * std::sin(phi) * std::sin(phi))));
}

TEST_CASE("bem: the propeller-brake region and its validity") {
    const Airfoil af = thin_plate();
    ElementInput in = element(af);
    in.theta = 0.3; // phi < 0 with Vx > 0: brake
    const BemOptions o = no_losses(false);
    const double phi = -0.3;
    const Residual r = bem_residual(in, o, phi);
    const double sigma = 3 * 2.0 / (2 * pi * 30);
    const double k =
        sigma * 2 * pi * (phi - 0.3) * std::cos(phi) / (4 * std::sin(phi) * std::sin(phi));
    CHECK(r.k == doctest::Approx(k));
    CHECK(r.a == doctest::Approx(k / (k - 1)));
    CHECK(r.valid == (k > 1));
    CHECK(r.f == doctest::Approx(std::sin(phi) * (1 - k) - std::cos(phi) * in.vx / in.vy));
}

TEST_CASE("bem: the tip node keeps a = 1 and the wake-free chord angle") {
    const Airfoil af = thin_plate();
    ElementInput in = element(af);
    in.z = in.z_tip;
    in.theta = 0.02;
    const ElementSolution s = solve_element(in, BemOptions{}, 1.225);
    CHECK(s.a == 1.0);
    CHECK(s.ap == 0.0);
    CHECK(s.phi == 0.0);
    CHECK(s.alpha == doctest::Approx(-0.02));
    CHECK(s.vrel == doctest::Approx(in.vy));
}

TEST_CASE("bem: Pitt/Peters scales the axial induction by 1 + K tan(chi/2) r/R sin(psi)") {
    const Airfoil af = thin_plate();
    ElementInput in = element(af);
    in.theta = design(in, 0.3, true).theta;
    BemOptions o = no_losses(true);
    const ElementSolution straight = solve_element(in, o, 1.225);
    o.skew_redistribution = true;
    in.chi0 = 0.3;
    in.psi = 1.1;
    in.tip_ratio = 0.8;
    const ElementSolution skewed = solve_element(in, o, 1.225);
    const double chi = (0.6 * straight.a + 1) * in.chi0;
    const double K = 15 * pi / 32;
    CHECK(skewed.a ==
          doctest::Approx(straight.a * (1 + K * std::tan(chi / 2) * 0.8 * std::sin(1.1)))
              .epsilon(1e-12));
    CHECK(skewed.ap == straight.ap);
    CHECK(skewed.phi ==
          doctest::Approx(std::atan2(in.vx * (1 - skewed.a), in.vy * (1 + skewed.ap))));
}

TEST_CASE("bem: every element gets a root or the wake-free angle") {
    const Airfoil af = stalling_plate();
    std::mt19937 gen(25);
    std::uniform_real_distribution<double> u(0, 1);
    int roots = 0;
    for (int i = 0; i < 2000; ++i) {
        ElementInput in = element(af);
        in.vx = -5 + 30 * u(gen);
        in.vy = -20 + 100 * u(gen);
        in.theta = -0.6 + 1.6 * u(gen);
        in.z = in.r = 2 + 60 * u(gen);
        in.chord = 0.5 + 4 * u(gen);
        const BemOptions o;
        const ElementSolution s = solve_element(in, o, 1.225);
        REQUIRE(std::isfinite(s.phi));
        REQUIRE(std::isfinite(s.fx));
        REQUIRE(std::isfinite(s.fy));
        if (s.valid) {
            ++roots;
            if (std::abs(in.vx) < 1e-3 || std::abs(in.vy) < 1e-3) continue;
            // A sign change of the residual within Brent's tolerance, or a zero.
            const double fl = bem_residual(in, o, s.phi_bem - 2e-6).f;
            const double fr = bem_residual(in, o, s.phi_bem + 2e-6).f;
            const double f0 = bem_residual(in, o, s.phi_bem).f;
            CHECK(((fl >= 0) != (fr >= 0) || std::abs(f0) < o.tolerance));
        } else {
            CHECK(s.a == 0.0);
            CHECK(s.phi == doctest::Approx(std::atan2(in.vx, in.vy)));
        }
    }
    CHECK(roots > 1900);
}

TEST_CASE("bem: the warm bracket finds AeroDyn's root to Brent's tolerance") {
    // Slowly changing inflow and pitch, as from step to step: each solve starts
    // from the last warm root; AeroDyn's full search from the same guess.
    const Airfoil af = stalling_plate();
    std::mt19937 gen(31);
    std::normal_distribution<double> n(0, 1);
    const BemOptions o;
    for (const double z : {10.0, 35.0, 60.0}) {
        ElementInput in = element(af);
        in.z = in.r = z;
        in.vy = 1.2 * z;
        BracketMemory memory;
        int known = 0;
        for (int i = 0; i < 400; ++i) {
            in.vx = std::clamp(in.vx + 0.05 * n(gen), 3.0, 25.0);
            in.vy = std::clamp(in.vy + 0.05 * n(gen), 5.0, 80.0);
            in.theta = std::clamp(in.theta + 0.002 * n(gen), -0.1, 0.4);
            const ElementSolution full = solve_inductions(in, o);
            const ElementSolution warm = solve_inductions(in, o, memory);
            REQUIRE(warm.valid == full.valid);
            CHECK(std::abs(warm.phi_bem - full.phi_bem) <= 4 * o.angle_tolerance);
            CHECK(warm.a_bem == doctest::Approx(full.a_bem).epsilon(1e-4));
            if (memory.ends_known) ++known;
            in.phi_guess = warm.phi_bem;
            in.guess_valid = warm.valid;
        }
        // The memory holds the momentum region's end signs nearly throughout.
        CHECK(known > 390);
    }
}
