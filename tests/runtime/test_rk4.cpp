// Fixed-step RK4: one step against its Taylor polynomial, global fourth order
// against the exact oscillator, the time grid, and failures as exceptions.
#include "runtime/test_models.hpp"

#include "yamsc/rk4.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace yamsc::runtime;

namespace {

// Largest error in x over the run against the exact solution.
double oscillator_error(double dt, const InputFunction& u,
                        double (*exact_x)(const test_oscillator::Params&, double),
                        const test_oscillator::Params& p, double x0) {
    const ModelView view = from_generated<test_oscillator::Model>(p);
    double worst = 0.0;
    simulate_rk4(view, {x0, 0.0}, u, 3.0, dt, [&](double t, const double* x) {
        worst = std::max(worst, std::abs(x[0] - exact_x(p, t)));
        return true;
    });
    return worst;
}

double constant_force_solution(const test_oscillator::Params& p, double t) {
    return reference::oscillator(p, 1.0, 0.1, 0.0, t).x;
}

// x'' + x = cos 2t from x(0) = 0.1, x'(0) = 0.
double cosine_force_solution(const test_oscillator::Params&, double t) {
    return (0.1 + 1.0 / 3.0) * std::cos(t) - std::cos(2.0 * t) / 3.0;
}

} // namespace

TEST_CASE("one RK4 step of y' = y is the fourth-order Taylor polynomial of e^h") {
    const OdeFunction f = [](double, const double* x, double* xdot) { xdot[0] = x[0]; };
    for (double h : {0.1, 0.5, -0.3}) {
        std::vector<double> y{1.0};
        rk4_step(f, 0.0, h, y);
        CHECK(y[0] == doctest::Approx(1.0 + h + h * h / 2 + h * h * h / 6 + h * h * h * h / 24)
                          .epsilon(1e-15));
    }
}

TEST_CASE("rk4_step evaluates f at the stage times") {
    // x' = t^3 is integrated exactly by Simpson's rule, which RK4 reduces to.
    const OdeFunction f = [](double t, const double*, double* xdot) { xdot[0] = t * t * t; };
    std::vector<double> x{0.0};
    rk4_step(f, 1.0, 0.5, x);
    CHECK(x[0] == doctest::Approx((std::pow(1.5, 4) - 1.0) / 4.0).epsilon(1e-15));
}

TEST_CASE("rk4_step with f(t, x) given calls f three times and takes the same step") {
    int calls = 0;
    const OdeFunction f = [&](double t, const double* x, double* xdot) {
        ++calls;
        xdot[0] = x[1];
        xdot[1] = -std::sin(x[0]) + 0.3 * std::cos(t);
    };
    Rk4Workspace work(2);
    double plain[2] = {0.4, -0.2}, given[2] = {0.4, -0.2}, f0[2];
    rk4_step(f, 0.7, 0.05, plain, work);
    CHECK(calls == 4);
    f(0.7, given, f0);
    calls = 0;
    rk4_step(f, 0.7, 0.05, given, work, f0);
    CHECK(calls == 3);
    CHECK(given[0] == plain[0]); // bit for bit
    CHECK(given[1] == plain[1]);
}

TEST_CASE("RK4 converges with order 4 on the damped oscillator") {
    const test_oscillator::Params p; // m = 2, c = 0.4, k = 50: 5 rad/s, zeta = 0.02
    const InputFunction force = constant_input({1.0});
    const double e1 = oscillator_error(0.02, force, constant_force_solution, p, 0.1);
    const double e2 = oscillator_error(0.01, force, constant_force_solution, p, 0.1);
    const double e3 = oscillator_error(0.005, force, constant_force_solution, p, 0.1);
    MESSAGE("max error in x at dt = 0.02, 0.01, 0.005: ", e1, ", ", e2, ", ", e3, "; ratios ",
            e1 / e2, ", ", e2 / e3);
    CHECK(e1 / e2 == doctest::Approx(16.0).epsilon(0.1));
    CHECK(e2 / e3 == doctest::Approx(16.0).epsilon(0.1));
    CHECK(e3 < 1e-7);
}

TEST_CASE("RK4 keeps order 4 with a time-varying input") {
    // Sampling the input only at the step start would drop the order to 1.
    test_oscillator::Params p;
    p.m = 1.0;
    p.c = 0.0;
    p.k = 1.0;
    const InputFunction force = [](double t, double* u) { u[0] = std::cos(2.0 * t); };
    const double e1 = oscillator_error(0.05, force, cosine_force_solution, p, 0.1);
    const double e2 = oscillator_error(0.025, force, cosine_force_solution, p, 0.1);
    MESSAGE("errors ", e1, ", ", e2, ", ratio ", e1 / e2);
    CHECK(e1 / e2 == doctest::Approx(16.0).epsilon(0.1));
}

TEST_CASE("the RK4 grid ends exactly at t_end and the observer can stop the run") {
    const ModelView view = from_generated<test_oscillator::Model>({});
    std::vector<double> times;
    const auto steps = simulate_rk4(view, {0.0, 0.0}, std::vector<double>{0.0}, 1.0, 0.3,
                                    [&](double t, const double*) {
                                        times.push_back(t);
                                        return true;
                                    });
    CHECK(steps == 4);
    REQUIRE(times.size() == 5);
    CHECK(times[3] == doctest::Approx(0.9));
    CHECK(times[4] == 1.0);

    times.clear();
    simulate_rk4(view, {0.0, 0.0}, std::vector<double>{0.0}, 1.0, 0.1,
                 [&](double t, const double*) {
                     times.push_back(t);
                     return t < 0.25;
                 });
    CHECK(times.size() == 4); // 0, 0.1, 0.2, 0.3 (the one that said stop)
}

TEST_CASE("RK4 reports bad arguments and divergence as exceptions") {
    test_oscillator::Params stiff;
    stiff.k = 1e6; // 707 rad/s: dt = 0.1 is far outside RK4's stability region
    const ModelView view = from_generated<test_oscillator::Model>(stiff);
    const StateObserver none;
    CHECK_THROWS_WITH_AS(
        simulate_rk4(view, {1.0, 0.0}, std::vector<double>{0.0}, 1000.0, 0.1, none),
        doctest::Contains("no longer finite"), std::runtime_error);
    CHECK_THROWS_AS(simulate_rk4(view, {1.0}, std::vector<double>{0.0}, 1.0, 0.1, none),
                    std::invalid_argument);
    CHECK_THROWS_AS(simulate_rk4(view, {1.0, 0.0}, std::vector<double>{}, 1.0, 0.1, none),
                    std::invalid_argument);
    CHECK_THROWS_AS(simulate_rk4(view, {1.0, 0.0}, std::vector<double>{0.0}, 1.0, 0.0, none),
                    std::invalid_argument);
    CHECK_THROWS_AS(simulate_rk4(view, {1.0, 0.0}, std::vector<double>{0.0}, -1.0, 0.1, none),
                    std::invalid_argument);
    CHECK_THROWS_AS(simulate_rk4(view, {NAN, 0.0}, std::vector<double>{0.0}, 1.0, 0.1, none),
                    std::invalid_argument);
}
