// ABM4 (ElastoDyn's Method 3): RK4 for the first three steps, then order 4 on
// the exact oscillator with two right-hand sides per step.
#include "runtime/test_models.hpp"

#include "yamsc/abm4.hpp"
#include "yamsc/rk4.hpp"
#include "yamsc/stepper.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace yamsc::runtime;

namespace {

// Largest error in x over a 3 s run of x'' + x = cos 2t against the exact solution.
double cosine_error(double dt, std::size_t* rhs_calls = nullptr) {
    test_oscillator::Params p;
    p.m = 1.0;
    p.c = 0.0;
    p.k = 1.0;
    ModelView view = from_generated<test_oscillator::Model>(p);
    std::size_t calls = 0;
    const auto rhs = view.rhs;
    view.rhs = [&](double t, const double* x, const double* u, double* xdot) {
        ++calls;
        rhs(t, x, u, xdot);
    };
    const InputFunction force = [](double t, double* u) { u[0] = std::cos(2.0 * t); };
    double worst = 0.0;
    simulate_abm4(view, {0.1, 0.0}, force, 3.0, dt, [&](double t, const double* x) {
        const double exact = (0.1 + 1.0 / 3.0) * std::cos(t) - std::cos(2.0 * t) / 3.0;
        worst = std::max(worst, std::abs(x[0] - exact));
        return true;
    });
    if (rhs_calls) *rhs_calls = calls;
    return worst;
}

} // namespace

TEST_CASE("ABM4 converges with order 4 at two right-hand sides per step") {
    std::size_t calls = 0;
    const double e1 = cosine_error(0.02);
    const double e2 = cosine_error(0.01);
    const double e3 = cosine_error(0.005, &calls);
    MESSAGE("max error in x at dt = 0.02, 0.01, 0.005: ", e1, ", ", e2, ", ", e3, "; ratios ",
            e1 / e2, ", ", e2 / e3);
    CHECK(e1 / e2 == doctest::Approx(16.0).epsilon(0.15));
    CHECK(e2 / e3 == doctest::Approx(16.0).epsilon(0.15));
    CHECK(e3 < 1e-9);
    // 600 steps: 3 RK4 steps (12 calls), then 597 steps of 2.
    CHECK(calls == 12 + 2 * 597);
}

TEST_CASE("the first three ABM4 steps are RK4 steps, the fourth is not") {
    const test_oscillator::Params p; // damped: m = 2, c = 0.4, k = 50
    const ModelView view = from_generated<test_oscillator::Model>(p);
    std::vector<std::vector<double>> rk4, abm4;
    auto keep = [](std::vector<std::vector<double>>& rows) {
        return [&rows](double, const double* x) {
            rows.push_back({x[0], x[1]});
            return true;
        };
    };
    simulate_rk4(view, {0.1, -0.5}, std::vector<double>{1.0}, 0.05, 0.01, keep(rk4));
    simulate_abm4(view, {0.1, -0.5}, constant_input({1.0}), 0.05, 0.01, keep(abm4));
    REQUIRE(rk4.size() == 6);
    REQUIRE(abm4.size() == 6);
    for (std::size_t k = 0; k <= 3; ++k) {
        CAPTURE(k);
        CHECK(abm4[k][0] == rk4[k][0]); // bit for bit
        CHECK(abm4[k][1] == rk4[k][1]);
    }
    CHECK(abm4[4][0] != rk4[4][0]);
    CHECK(abm4[4][0] == doctest::Approx(rk4[4][0]).epsilon(1e-6));
}

TEST_CASE("one ABM4 step on a cubic is exact, as the formulas are") {
    // x' = 4 t^3: AB4 and AM4 integrate polynomials of degree 3 in t exactly.
    const OdeFunction f = [](double t, const double*, double* xdot) { xdot[0] = 4 * t * t * t; };
    Abm4Integrator abm4(f, 1);
    double x = 0.0;
    const double h = 0.1;
    for (int k = 0; k < 8; ++k) abm4.step(k * h, h, &x);
    CHECK(abm4.history() == 4);
    CHECK(x == doctest::Approx(std::pow(0.8, 4)).epsilon(1e-13));
}

TEST_CASE("ABM4 steps with f(t, x) given skip that call and are the same steps") {
    int calls = 0;
    const OdeFunction f = [&](double t, const double* x, double* xdot) {
        ++calls;
        xdot[0] = x[1];
        xdot[1] = -std::sin(x[0]) + 0.3 * std::cos(t);
    };
    Abm4Integrator plain(f, 2), given(f, 2);
    double a[2] = {0.4, -0.2}, b[2] = {0.4, -0.2}, f0[2];
    for (int k = 0; k < 6; ++k) { // 3 RK4 steps, then ABM4
        const double t = 0.05 * k;
        calls = 0;
        plain.step(t, 0.05, a);
        const int without = calls;
        f(t, b, f0);
        calls = 0;
        given.step(t, 0.05, b, f0);
        CHECK(calls == without - 1);
        CHECK(b[0] == a[0]); // bit for bit
        CHECK(b[1] == a[1]);
    }
}

TEST_CASE("ABM4 restarts with RK4 when the step changes, and reports divergence") {
    const OdeFunction f = [](double, const double* x, double* xdot) { xdot[0] = -x[0]; };
    Abm4Integrator abm4(f, 1);
    double x = 1.0;
    for (int k = 0; k < 5; ++k) abm4.step(0.1 * k, 0.1, &x);
    CHECK(abm4.history() == 4);
    abm4.step(0.5, 0.05, &x); // a shorter step: RK4, the history starts again
    CHECK(abm4.history() == 1);
    CHECK(x == doctest::Approx(std::exp(-0.55)).epsilon(1e-5));

    test_oscillator::Params stiff;
    stiff.k = 1e6;
    const ModelView view = from_generated<test_oscillator::Model>(stiff);
    CHECK_THROWS_WITH_AS(simulate_abm4(view, {1.0, 0.0}, constant_input({0.0}), 100.0, 0.1, {}),
                         doctest::Contains("ABM4"), std::runtime_error);
    FixedStepper stepper(Method::abm4, f, 1);
    double y = 1.0;
    for (int k = 0; k < 10; ++k) stepper.step(0.01 * k, 0.01, &y);
    CHECK(y == doctest::Approx(std::exp(-0.1)).epsilon(1e-9));
    CHECK_THROWS_AS(FixedStepper(Method::cvode, f, 1), std::invalid_argument);
}
