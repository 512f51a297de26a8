// runtime::trim on hand-made views with closed-form equilibria: a pendulum
// under gravity and a torque (sin q* = tau / (m g l)), a spring-mass pair with
// a rigid DOF beside it (left where it is), a held DOF, and a load without an
// equilibrium (reported, not converged).
#include <yamsc/trim.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

using namespace yamsc::runtime;

namespace {

/// m l² q'' = tau - m g l sin q; a torque tau holds it at asin(tau / (m g l)).
ModelView torque_pendulum(double m, double l, double g) {
    ModelView v;
    v.nq = 1;
    v.nu = 1;
    v.dof_names = {"phi"};
    v.input_names = {"tau"};
    v.forcing = [=](double, const double* q, const double*, const double* u, double* F) {
        F[0] = u[0] - m * g * l * std::sin(q[0]);
    };
    v.jacobians = [=](double, const double* q, const double*, const double*, double* dq,
                      double* dqd, double* du) {
        dq[0] = -m * g * l * std::cos(q[0]);
        dqd[0] = 0;
        du[0] = 1;
    };
    return v;
}

/// x: a spring k under a weight m g (x* = -m g / k); s: rigid, no load; r:
/// a rotor whose equation carries a constant torque T (no equilibrium).
ModelView spring_and_rigid(double m, double g, double k, double T) {
    ModelView v;
    v.nq = 3;
    v.nu = 0;
    v.dof_names = {"x", "s", "r"};
    v.forcing = [=](double, const double* q, const double*, const double*, double* F) {
        F[0] = -k * q[0] - m * g;
        F[1] = 0;
        F[2] = T;
    };
    v.jacobians = [=](double, const double*, const double*, const double*, double* dq, double* dqd,
                      double*) {
        for (int i = 0; i < 9; ++i) dq[i] = dqd[i] = 0;
        dq[0] = -k;
    };
    return v;
}

} // namespace

TEST_CASE("trim: a pendulum held by a torque settles at asin(tau / (m g l))") {
    const double m = 1.3, l = 0.9, g = 9.81, tau = 4.2;
    const ModelView v = torque_pendulum(m, l, g);
    for (double start : {0.0, 1.2, -0.3}) {
        CAPTURE(start);
        const TrimResult r = trim(v, {start}, {0.0}, {tau}, {false});
        CHECK(r.converged);
        CHECK(r.q[0] == doctest::Approx(std::asin(tau / (m * g * l))).epsilon(1e-14));
        CHECK(std::fabs(r.residual[0]) <= r.tolerance);
        CHECK(r.iterations <= 8);
    }
}

TEST_CASE("trim: a rigid DOF without load stays; a held DOF keeps its value and reports its "
          "load") {
    const double m = 2.0, g = 9.81, k = 500.0;
    const ModelView v = spring_and_rigid(m, g, k, 0.0);
    TrimResult r = trim(v, {0.3, 0.7, 0.1}, {0, 0, 0}, {}, {false, false, false});
    CHECK(r.converged);
    CHECK(r.q[0] == doctest::Approx(-m * g / k).epsilon(1e-14));
    CHECK(r.q[1] == 0.7); // the minimum-norm step never moves a direction without stiffness
    CHECK(r.q[2] == 0.1);

    // Held: x stays at 0.3 and its residual is the force that holds it there.
    r = trim(v, {0.3, 0.7, 0.1}, {0, 0, 0}, {}, {true, false, false});
    CHECK(r.converged);
    CHECK(r.q[0] == 0.3);
    CHECK(r.residual[0] == doctest::Approx(-k * 0.3 - m * g));
}

TEST_CASE("trim: a constant load on a DOF without stiffness has no equilibrium") {
    const ModelView v = spring_and_rigid(2.0, 9.81, 500.0, 3.0);
    const TrimResult r = trim(v, {0, 0, 0}, {0, 0, 0}, {}, {false, false, false});
    CHECK_FALSE(r.converged);
    CHECK(r.residual[2] == 3.0);
    // Holding that DOF makes the rest solvable.
    CHECK(trim(v, {0, 0, 0}, {0, 0, 0}, {}, {false, false, true}).converged);
}

TEST_CASE("trim: wrong sizes and missing routines are errors") {
    ModelView v = torque_pendulum(1, 1, 9.81);
    CHECK_THROWS_AS(trim(v, {0, 0}, {0}, {1}, {false}), std::invalid_argument);
    v.jacobians = nullptr;
    CHECK_THROWS_WITH_AS(trim(v, {0}, {0}, {1}, {false}), doctest::Contains("compiled without"),
                         std::invalid_argument);
}

TEST_CASE("trim --adjust: the torque that holds a pendulum at a set angle, and a coupled input") {
    // phi held at 0.5 rad: tau balances gravity, tau = m g l sin(0.5).
    const double m = 1.3, l = 0.9, g = 9.81;
    const ModelView pendulum = torque_pendulum(m, l, g);
    const TrimResult r = trim(pendulum, {0.5}, {0.0}, {0.0}, {true}, 0.0, {}, {{0}, {0}});
    CHECK(r.converged);
    CHECK(r.q[0] == 0.5);
    CHECK(r.u[0] == doctest::Approx(m * g * l * std::sin(0.5)).epsilon(1e-14));
    CHECK(std::fabs(r.residual[0]) <= r.tolerance);

    // A spring x loaded by the input (c u) and a held rotor r driven by T - u:
    // balancing r needs u = T, and x then settles at (c T - m g) / k.
    const double k = 500, c = 3, T = 40;
    ModelView v;
    v.nq = 2;
    v.nu = 1;
    v.forcing = [=](double, const double* q, const double*, const double* u, double* F) {
        F[0] = -k * q[0] - m * g + c * u[0];
        F[1] = T - u[0];
    };
    v.jacobians = [=](double, const double*, const double*, const double*, double* dq, double* dqd,
                      double* du) {
        for (int i = 0; i < 4; ++i) dq[i] = dqd[i] = 0;
        dq[0] = -k;
        du[0] = c;
        du[1] = -1;
    };
    const TrimResult s = trim(v, {0, 0}, {0, 2.0}, {0}, {false, true}, 0.0, {}, {{0}, {1}});
    CHECK(s.converged);
    CHECK(s.u[0] == doctest::Approx(T).epsilon(1e-14));
    CHECK(s.q[0] == doctest::Approx((c * T - m * g) / k).epsilon(1e-14));
    // Without the adjustment the held DOF keeps its load: T - u.
    const TrimResult plain = trim(v, {0, 0}, {0, 2.0}, {0}, {false, true});
    CHECK(plain.u[0] == 0.0);
    CHECK(plain.residual[1] == doctest::Approx(T));
}

TEST_CASE("trim --adjust: one input per held DOF, each once, and only held DOFs") {
    const ModelView v = torque_pendulum(1, 1, 9.81);
    CHECK_THROWS_WITH_AS(trim(v, {0}, {0}, {1}, {true}, 0.0, {}, {{0}, {}}),
                         doctest::Contains("each adjusted input"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(trim(v, {0}, {0}, {1}, {false}, 0.0, {}, {{0}, {0}}),
                         doctest::Contains("only a held DOF"), std::invalid_argument);
    CHECK_THROWS_AS(trim(v, {0}, {0}, {1}, {true}, 0.0, {}, {{1}, {0}}), std::invalid_argument);
}
