// The simple pendulum: closed-form M and F, and the small-amplitude period of its
// generated code integrated by the runtime.
#include "equations_fixture.hpp"

#include <yamsc/simulation.hpp>

using namespace yamsc;

TEST_CASE("pendulum: M = m L^2 and F = -m g L sin(theta)") {
    auto eq = test::derive_file("models/pendulum.mbd");
    REQUIRE(eq.nq() == 1);
    const double m = 1.7, L = 0.8, g = 9.81;
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> angle(-3, 3);
    for (int k = 0; k < 10; ++k) {
        double th = angle(rng), thd = angle(rng);
        auto v = test::evaluate(eq, {th}, {thd}, {}, {{"m", m}, {"L", L}});
        CHECK(v.M[0][0] == doctest::Approx(m * L * L).epsilon(1e-14));
        CHECK(v.F[0] == doctest::Approx(-m * g * L * std::sin(th)).epsilon(1e-13));
    }
}

TEST_CASE("pendulum: small-amplitude period 2 pi sqrt(L/g) from the generated code") {
    auto eq = test::derive_file("models/pendulum.mbd");
    auto c = test::compile_model(eq, {{"L", 2.0}});
    runtime::SimulationOptions o;
    o.t_end = 20;
    o.dt = 1e-3;
    o.x0 = {1e-3, 0};
    auto r = runtime::simulate(c.view, o);
    // Period from the first and last upward zero crossings of theta (interpolated).
    std::vector<double> crossings;
    for (std::size_t i = 1; i < r.rows(); ++i) {
        double a = r.state_row(i - 1)[0], b = r.state_row(i)[0];
        if (a < 0 && b >= 0)
            crossings.push_back(r.time[i - 1] + (r.time[i] - r.time[i - 1]) * (-a) / (b - a));
    }
    REQUIRE(crossings.size() >= 3);
    double period =
        (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    double exact = 2 * M_PI * std::sqrt(2.0 / 9.81); // amplitude correction (1 + th0^2/16) ~ 6e-8
    CHECK(period == doctest::Approx(exact).epsilon(1e-6));
}
