// The simulation driver: columns, rows, outputs, both methods, progress and
// cancellation, option checking.
#include "runtime/test_models.hpp"

#include "yamsc/simulation.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace yamsc::runtime;

namespace {

SimulationOptions oscillator_options(Method method) {
    SimulationOptions o;
    o.t_end = 2.0;
    o.dt = 0.01;
    o.method = method;
    o.rtol = 1e-10;
    o.atol = 1e-12;
    o.x0 = {0.1, -0.5};
    o.u = {1.0};
    return o;
}

} // namespace

TEST_CASE("columns are time, DOFs, DOF rates, outputs") {
    const auto oscillator = from_generated<test_oscillator::Model>({});
    CHECK(column_names(oscillator) ==
          std::vector<std::string>{"time", "x", "x'", "spring_force", "kinetic_energy"});
    const auto chain = from_generated<test_two_masses::Model>({});
    CHECK(column_names(chain) == std::vector<std::string>{"time", "x1", "x2", "x1'", "x2'"});
}

TEST_CASE("both methods fill the same grid with states and outputs matching the exact solution") {
    const test_oscillator::Params p;
    const auto view = from_generated<test_oscillator::Model>(p);
    for (Method method : {Method::rk4, Method::abm4, Method::cvode}) {
        const std::string name = method_name(method);
        CAPTURE(name);
        const SimulationResult r = simulate(view, oscillator_options(method));
        REQUIRE(r.rows() == 201);
        CHECK(r.completed);
        CHECK(r.column_count() == 5);
        CHECK(r.time.front() == 0.0);
        CHECK(r.time.back() == 2.0);
        CHECK(r.time[100] == doctest::Approx(1.0).epsilon(1e-15));
        CHECK(r.state_row(0)[0] == 0.1);
        CHECK(r.state_row(0)[1] == -0.5);
        double worst = 0.0;
        for (std::size_t i = 0; i < r.rows(); ++i) {
            const auto exact = reference::oscillator(p, 1.0, 0.1, -0.5, r.time[i]);
            worst = std::max(worst, std::abs(r.value(i, 1) - exact.x));
            // Outputs are evaluated on the recorded state.
            CHECK(r.value(i, 3) == doctest::Approx(p.k * r.value(i, 1)).epsilon(1e-14));
            CHECK(r.value(i, 4) ==
                  doctest::Approx(0.5 * p.m * r.value(i, 2) * r.value(i, 2)).epsilon(1e-14));
        }
        MESSAGE(std::string(method_name(method)), ": max error in x ", worst);
        // ABM4's error constant is about 2.5x RK4's at the same step.
        CHECK(worst < (method == Method::abm4 ? 3e-7 : 1e-7));
    }
}

TEST_CASE("a time-varying input reaches the outputs at the right time") {
    // kinetic energy does not see u, but the state does: check the run uses u(t).
    test_oscillator::Params p;
    p.m = 1.0;
    p.c = 0.0;
    p.k = 1.0;
    SimulationOptions o = oscillator_options(Method::rk4);
    o.x0 = {0.1, 0.0};
    o.u = {};
    o.u_of_t = [](double t, double* u) { u[0] = std::cos(2.0 * t); };
    const auto r = simulate(from_generated<test_oscillator::Model>(p), o);
    const double t = r.time.back();
    CHECK(r.value(r.rows() - 1, 1) ==
          doctest::Approx((0.1 + 1.0 / 3.0) * std::cos(t) - std::cos(2.0 * t) / 3.0).epsilon(1e-8));
}

TEST_CASE("progress is reported about every percent and can stop the run") {
    const auto view = from_generated<test_oscillator::Model>({});
    SimulationOptions o = oscillator_options(Method::rk4);
    o.dt = 0.001; // 2001 rows
    std::vector<double> reported;
    auto r = simulate(view, o, [&](double t, double t_end) {
        CHECK(t_end == 2.0);
        reported.push_back(t);
        return true;
    });
    CHECK(r.completed);
    CHECK(reported.size() >= 99);
    CHECK(reported.size() <= 101);
    CHECK(reported.back() == 2.0);
    for (std::size_t i = 1; i < reported.size(); ++i) CHECK(reported[i] > reported[i - 1]);

    for (Method method : {Method::rk4, Method::cvode}) {
        o.method = method;
        r = simulate(view, o, [](double t, double) { return t < 0.5; });
        CHECK_FALSE(r.completed);
        CHECK(r.time.back() == doctest::Approx(0.5).epsilon(0.05));
        CHECK(r.states.size() == r.rows() * 2);
        CHECK(r.outputs.size() == r.rows() * 2);
    }
}

TEST_CASE("inconsistent options are rejected before integrating") {
    const auto view = from_generated<test_oscillator::Model>({});
    SimulationOptions o = oscillator_options(Method::rk4);
    o.x0 = {0.1};
    CHECK_THROWS_WITH_AS(simulate(view, o), doctest::Contains("initial state has 1 values"),
                         std::invalid_argument);
    o = oscillator_options(Method::cvode);
    o.u = {};
    CHECK_THROWS_AS(simulate(view, o), std::invalid_argument);
    o = oscillator_options(Method::cvode);
    o.x0 = {0.1, INFINITY};
    CHECK_THROWS_WITH_AS(simulate(view, o), doctest::Contains("x'"), std::invalid_argument);
    o = oscillator_options(Method::rk4);
    o.dt = -0.1;
    CHECK_THROWS_AS(simulate(view, o), std::invalid_argument);
}

TEST_CASE("method names") {
    CHECK(parse_method("rk4") == Method::rk4);
    CHECK(parse_method("cvode") == Method::cvode);
    CHECK(parse_method("abm4") == Method::abm4);
    CHECK(std::string(method_name(Method::abm4)) == "abm4");
    CHECK_FALSE(parse_method("euler").has_value());
    CHECK(std::string(method_name(Method::cvode)) == "cvode");
}

TEST_CASE("dt_out stores every n-th row and the last, with the outputs of the full run") {
    const auto view = from_generated<test_oscillator::Model>({});
    for (Method method : {Method::rk4, Method::abm4}) {
        CAPTURE(method_name(method));
        SimulationOptions o = oscillator_options(method);
        o.t_end = 2.005; // the last step is shortened: stored although off the dt_out grid
        const SimulationResult every = simulate(view, o);
        o.dt_out = 0.04;
        const SimulationResult sparse = simulate(view, o);
        REQUIRE(every.rows() == 202);
        REQUIRE(sparse.rows() == 52); // 0, 0.04, .., 2.0 and 2.005
        for (std::size_t i = 0; i + 1 < sparse.rows(); ++i) {
            CHECK(sparse.time[i] == every.time[4 * i]);
            for (std::size_t j = 0; j < every.column_count(); ++j)
                CHECK(sparse.value(i, j) == every.value(4 * i, j)); // bit for bit
        }
        CHECK(sparse.time.back() == 2.005);
        CHECK(sparse.value(51, 1) == every.value(201, 1));
        CHECK(sparse.value(51, 3) == every.value(201, 3));
    }
    CHECK(output_stride(0.01, 0.0) == 1);
    CHECK(output_stride(0.005, 0.01) == 2);
    CHECK(output_stride(0.00625, 0.025) == 4);
    CHECK_THROWS_AS(output_stride(0.01, 0.015), std::invalid_argument);
    CHECK_THROWS_AS(output_stride(0.01, 0.001), std::invalid_argument);
}
