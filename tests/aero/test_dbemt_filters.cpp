// Øye's dynamic-inflow filters (AeroDyn's DBEMT) against their closed forms.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "yamsc/aero/dynamic_inflow.hpp"

using namespace yamsc::aero;

namespace {

constexpr double k = Dbemt::k_0ye;

// One blade of two nodes at 0.35 R and R (k_tau 0.358 and 0.13).
std::vector<double> two_nodes() {
    return {17.5, 50.0};
}

double k_tau_of(double s) {
    return 0.39 - 0.26 * s * s;
}

// W(t) for W_qs stepping 0 -> 1 at t = 0 with both filters at rest: W_int jumps to k,
// then relaxes with tau1; W follows with tau2 = k_tau tau1.
double step_response(double t, double tau1, double kt) {
    const double tau2 = kt * tau1;
    const double c = (1 - k) / (1 - kt);
    return 1 - c * std::exp(-t / tau1) + (c - 1) * std::exp(-t / tau2);
}

void set_all(DbemtInput& u, double axial, double tangential) {
    for (auto& q : u.quasi_steady) q = {axial, tangential};
}

} // namespace

TEST_CASE("dbemt: constant tau1, the discrete update is exact for a constant input") {
    // W_int and W start at 0 and the input is 1 from t = 0 on (no jump of W_int):
    // W_int = 1 - e^{-t/tau1}, W = 1 - e^{-t/tau1}/(1 - k_tau) + k_tau/(1 - k_tau) e^{-t/tau2}.
    const double tau1 = 4, dt = 0.05;
    const Dbemt d(DynamicInflow::constant_tau1, tau1, dt, 1, 2, two_nodes());
    DbemtInput u0 = d.make_input(), u1 = d.make_input();
    DbemtState x = d.make_state();
    set_all(u0, 0, 0);
    d.initialize(u0, x);
    set_all(u1, 1, -0.5);
    for (int n = 1; n <= 400; ++n) {
        d.update(u1, u1, x);
        const double t = n * dt;
        for (std::size_t e = 0; e < 2; ++e) {
            const double kt = k_tau_of(e == 0 ? 0.35 : 1.0);
            const double w_int = 1 - std::exp(-t / tau1);
            const double w =
                1 - std::exp(-t / tau1) / (1 - kt) + kt / (1 - kt) * std::exp(-t / (kt * tau1));
            REQUIRE(x.element[e].vind_1.axial == doctest::Approx(w_int).epsilon(1e-12));
            REQUIRE(x.element[e].vind.axial == doctest::Approx(w).epsilon(1e-12));
            REQUIRE(x.element[e].vind.tangential == doctest::Approx(-0.5 * w).epsilon(1e-12));
        }
    }
    CHECK(x.tau1 == 4.0);
}

TEST_CASE("dbemt: constant tau1, a step of the quasi-steady induction") {
    // The input rises from 0 to 1 within the first step (linearly, as AeroDyn
    // interpolates it): the response is the step response averaged over delays in
    // [0, dt], W_step(t - dt/2) + dt^2/24 W_step''(t - dt/2) + O(dt^4).
    const double tau1 = 3, dt = 0.00625;
    const Dbemt d(DynamicInflow::constant_tau1, tau1, dt, 1, 2, two_nodes());
    DbemtInput u0 = d.make_input(), u1 = d.make_input();
    DbemtState x = d.make_state();
    set_all(u0, 0, 0);
    set_all(u1, 1, 1);
    d.update(u0, u1, x);
    CHECK(x.element[1].vind_1.axial == doctest::Approx(k).epsilon(0.01)); // W_int's jump
    double worst = 0;
    for (int n = 2; n <= 3200; ++n) {
        d.update(u1, u1, x);
        const double t = n * dt - dt / 2;
        for (std::size_t e = 0; e < 2; ++e) {
            const double exact = step_response(t, tau1, k_tau_of(e == 0 ? 0.35 : 1.0));
            worst = std::max(worst, std::abs(x.element[e].vind.axial - exact));
            worst = std::max(worst, std::abs(x.element[e].vind.tangential - exact));
        }
    }
    // The largest |W''| is at t = 0 on the tip element (the shortest tau2).
    const double kt = k_tau_of(1.0), tau2 = kt * tau1, c = (1 - k) / (1 - kt);
    const double bound = dt * dt / 24 * std::abs(-c / (tau1 * tau1) + (c - 1) / (tau2 * tau2));
    CHECK(worst < bound);
    CHECK(worst > 0.9 * bound);
    // At 20 s the filters have settled.
    CHECK(x.element[0].vind.axial == doctest::Approx(1.0).epsilon(1e-2));
}

TEST_CASE("dbemt: the continuous form (DBEMT_Mod 3) equals the discrete one (DBEMT_Mod 1)") {
    // Both solve the same equations for the same piecewise-linear input, DBEMT_Mod 1
    // exactly, DBEMT_Mod 3 with RK4: they differ by RK4's O(dt^4) error.
    auto input = [](double t) {
        const double w = -2 + 0.5 * std::sin(1.3 * t) - 0.75 * (1 + std::tanh((t - 3) / 0.2));
        return InducedVelocity{w, 0.1 * std::cos(0.7 * t)};
    };
    auto difference = [&](double dt) {
        const double tau1 = 2.5;
        const Dbemt d1(DynamicInflow::constant_tau1, tau1, dt, 1, 2, two_nodes());
        const Dbemt d3(DynamicInflow::continuous, tau1, dt, 1, 2, two_nodes());
        DbemtInput ua = d1.make_input(), ub = d1.make_input();
        DbemtState x1 = d1.make_state(), x3 = d3.make_state();
        double worst = 0, lag = 0;
        for (int n = 0; n * dt < 15; ++n) {
            for (std::size_t e = 0; e < 2; ++e) {
                ua.quasi_steady[e] = input(n * dt);
                ub.quasi_steady[e] = input((n + 1) * dt);
            }
            d1.update(ua, ub, x1);
            d3.update(ua, ub, x3);
            for (std::size_t e = 0; e < 2; ++e) {
                const DbemtElementState &s1 = x1.element[e], &s3 = x3.element[e];
                const InducedVelocity q = ub.quasi_steady[e];
                worst = std::max(worst, std::abs(s1.vind.axial - s3.vind.axial));
                worst = std::max(worst, std::abs(s1.vind.tangential - s3.vind.tangential));
                // W_red = W_int - k W_qs
                worst = std::max(worst, std::abs(s1.vind_1.axial - k * q.axial - s3.vind_1.axial));
                lag = std::max(lag, std::abs(s1.vind.axial - q.axial));
            }
        }
        CHECK(lag > 0.3); // the filters lag the input visibly
        return worst;
    };
    const double coarse = difference(0.02), fine = difference(0.01);
    CHECK(fine < 1e-8); // of an input of size 2 to 4
    CHECK(coarse / fine == doctest::Approx(16).epsilon(0.25));
}

TEST_CASE("dbemt: a jump of the input between two updates") {
    // AeroDyn's inputs make a change of the wind such a jump. DBEMT_Mod 3 holds
    // W_red = W_int - k W_qs, so W_int jumps by k and W follows the step response;
    // DBEMT_Mod 1 holds W_int, which starts from where it was (the first test's curve).
    const double tau1 = 4, dt = 0.01;
    const Dbemt d3(DynamicInflow::continuous, tau1, dt, 1, 2, two_nodes());
    DbemtInput u0 = d3.make_input(), u1 = d3.make_input();
    DbemtState x = d3.make_state();
    set_all(u0, 0, 0);
    d3.initialize(u0, x);
    set_all(u1, 1, 1);
    double worst = 0;
    for (int n = 1; n <= 1000; ++n) {
        d3.update(u1, u1, x);
        for (std::size_t e = 0; e < 2; ++e) {
            const double exact = step_response(n * dt, tau1, k_tau_of(e == 0 ? 0.35 : 1.0));
            worst = std::max(worst, std::abs(x.element[e].vind.axial - exact));
        }
    }
    CHECK(worst < 1e-8);
}

TEST_CASE("dbemt: derivative, packing and the steady state") {
    const Dbemt d(DynamicInflow::continuous, 2.0, 0.01, 2, 2, {10, 40, 10, 40});
    DbemtInput u = d.make_input();
    DbemtState x = d.make_state();
    for (std::size_t e = 0; e < 4; ++e) u.quasi_steady[e] = {-1.0 - double(e), 0.2};
    d.initialize(u, x);
    CHECK(x.element[3].vind_1.axial == doctest::Approx(-4 * (1 - k)));
    std::vector<double> flat(4 * Dbemt::states_per_element), dxdt(flat.size());
    Dbemt::pack(x, flat.data());
    d.derivative(u, flat.data(), dxdt.data());
    for (double v : dxdt) CHECK(v == doctest::Approx(0.0).epsilon(1e-15)); // at rest
    // A unit offset of W decays with tau2 = k_tau tau1 (r/R = 0.25 at element 0).
    flat[0] += 1;
    d.derivative(u, flat.data(), dxdt.data());
    CHECK(dxdt[0] == doctest::Approx(-1 / (k_tau_of(0.25) * 2.0)));
    DbemtState y = d.make_state();
    Dbemt::unpack(flat.data(), y);
    CHECK(y.element[0].vind.axial == doctest::Approx(0.0)); // -1 + 1
    CHECK(y.element[2].vind.tangential == doctest::Approx(0.2));
    // Before any update the output is the quasi-steady input.
    const DbemtState fresh = d.make_state();
    CHECK(d.output(u, fresh, 1).axial == doctest::Approx(-2.0));
}

TEST_CASE("dbemt: DBEMT_Mod 2's time constants") {
    const Dbemt d(DynamicInflow::varying_tau1, 0.0, 0.01, 1, 2, two_nodes());
    DbemtInput u = d.make_input();
    u.rlocal = {20.0, 60.0};
    const double a[2] = {0.3, 0.3};
    d.set_disk_input(u, a, 11.0);
    CHECK(u.disk.radius == 60.0);
    // tau1 = 1.1 R / ((1 - 1.3 a) U)
    CHECK(d.tau1(u.disk) == doctest::Approx(1.1 * 60 / ((1 - 1.3 * u.disk.axial_induction) * 11)));
    CHECK(d.k_tau(u, 0) == doctest::Approx(0.39 - 0.26 / 9));
    CHECK(d.k_tau(u, 1) == doctest::Approx(0.13));
    // Bounds: a at most 0.5, U at least 0.1 m/s, tau1 at most 100 s.
    CHECK(d.tau1({0.9, 10, 60}) == doctest::Approx(1.1 * 60 / (0.35 * 10)));
    CHECK(d.tau1({0.1, 0.0, 63}) == doctest::Approx(100.0));
    CHECK(d.tau1({0.0, 0.0, 0.5}) == doctest::Approx(1.1 * 0.5 / 0.1));
    // Constant tau1 models ignore the disk.
    const Dbemt c(DynamicInflow::constant_tau1, 4.0, 0.01, 1, 2, two_nodes());
    CHECK(c.tau1({0.3, 11, 63}) == 4.0);
}

TEST_CASE("dbemt: the disk-averaged axial induction weighs 0.6 R to 0.8 R") {
    // Ten nodes per blade at 0.1 R .. R, two blades: only 0.7 R has weight inside the
    // open kernel support, so the average is that node's induction.
    std::vector<double> r;
    for (int b = 0; b < 2; ++b)
        for (int i = 1; i <= 10; ++i) r.push_back(6.3 * i);
    const Dbemt d(DynamicInflow::varying_tau1, 0.0, 0.01, 2, 10, r);
    DbemtInput u = d.make_input();
    u.rlocal = r;
    std::vector<double> a(20, 0.9);
    a[6] = 0.2;  // blade 1 at 0.7 R
    a[16] = 0.4; // blade 2 at 0.7 R
    d.set_disk_input(u, a.data(), 9.0);
    CHECK(u.disk.axial_induction == doctest::Approx(0.3));
    CHECK(u.disk.normal_speed == 9.0);
    CHECK(u.disk.radius == doctest::Approx(63.0));
}

TEST_CASE("dbemt: induction factors from induced velocities") {
    const InducedVelocity w = induced_velocity({0.3, 0.01}, 10.0, 50.0);
    CHECK(w.axial == doctest::Approx(-3.0));
    CHECK(w.tangential == doctest::Approx(0.5));
    const InductionFactors f = induction_factors(w, 10.0, 50.0);
    CHECK(f.axial == doctest::Approx(0.3));
    CHECK(f.tangential == doctest::Approx(0.01));
    CHECK(induction_factors({-30.0, -80.0}, 10.0, 50.0).axial == 1.5); // limited
    CHECK(induction_factors({-30.0, -80.0}, 10.0, 50.0).tangential == -1.0);
    CHECK(induction_factors({-3.0, 1.0}, 0.0, 50.0).axial == 0.0);
}

TEST_CASE("dbemt: bad parameters are refused") {
    CHECK_THROWS_AS(Dbemt(DynamicInflow::none, 4, 0.01, 1, 2, two_nodes()), std::invalid_argument);
    CHECK_THROWS_AS(Dbemt(DynamicInflow::constant_tau1, 0, 0.01, 1, 2, two_nodes()),
                    std::invalid_argument);
    CHECK_THROWS_AS(Dbemt(DynamicInflow::continuous, 4, 0.0, 1, 2, two_nodes()),
                    std::invalid_argument);
    CHECK_THROWS_AS(Dbemt(DynamicInflow::constant_tau1, 4, 0.01, 1, 2, {0.0, 50.0}),
                    std::invalid_argument);
    CHECK_THROWS_AS(Dbemt(DynamicInflow::constant_tau1, 4, 0.01, 1, 3, two_nodes()),
                    std::invalid_argument);
    CHECK_NOTHROW(Dbemt(DynamicInflow::varying_tau1, 0, 0.01, 1, 2, {0.0, 50.0}));
}
