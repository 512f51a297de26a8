// The planar double pendulum against its closed-form Lagrange equations, with an
// elbow spring-damper, a torque on the first link and a tip force.
#include "equations_fixture.hpp"

using namespace yamsc;

TEST_CASE("double pendulum: M and F match the closed form at random states") {
    auto eq = test::derive_file("models/double_pendulum.mbd");
    REQUIRE(eq.nq() == 2);
    REQUIRE(eq.nu() == 2);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-2.5, 2.5), P(0.3, 3.0);
    for (int k = 0; k < 20; ++k) {
        const double m1 = P(rng), m2 = P(rng), L1 = P(rng), L2 = P(rng), g = 9.81;
        const double kk = P(rng), c = P(rng), tau = U(rng), f = U(rng);
        const double t1 = U(rng), t2 = U(rng), w1 = U(rng), w2 = U(rng);
        auto v =
            test::evaluate(eq, {t1, t2}, {w1, w2}, {tau, f},
                           {{"m1", m1}, {"m2", m2}, {"L1", L1}, {"L2", L2}, {"k", kk}, {"c", c}});
        const double c2 = std::cos(t2), s2 = std::sin(t2), s1 = std::sin(t1),
                     s12 = std::sin(t1 + t2);
        const double M11 = (m1 + m2) * L1 * L1 + m2 * L2 * L2 + 2 * m2 * L1 * L2 * c2;
        const double M12 = m2 * L2 * L2 + m2 * L1 * L2 * c2;
        const double M22 = m2 * L2 * L2;
        const double bias1 = -m2 * L1 * L2 * s2 * w2 * (2 * w1 + w2);
        const double bias2 = m2 * L1 * L2 * s2 * w1 * w1;
        const double dV1 = m1 * g * L1 * s1 + m2 * g * (L1 * s1 + L2 * s12);
        const double dV2 = m2 * g * L2 * s12;
        const double Q1 = tau + f * (-L1 * std::cos(t1) - L2 * std::cos(t1 + t2));
        const double Q2 = f * (-L2 * std::cos(t1 + t2)) - kk * t2 - c * w2;
        const double scale = std::max({std::fabs(M11), 1.0});
        CHECK(v.M[0][0] == doctest::Approx(M11).epsilon(1e-12));
        CHECK(v.M[0][1] == doctest::Approx(M12).epsilon(1e-12));
        CHECK(v.M[1][0] == v.M[0][1]);
        CHECK(v.M[1][1] == doctest::Approx(M22).epsilon(1e-12));
        CHECK(std::fabs(v.F[0] - (Q1 - bias1 - dV1)) < 1e-12 * scale * 10);
        CHECK(std::fabs(v.F[1] - (Q2 - bias2 - dV2)) < 1e-12 * scale * 10);
    }
}
