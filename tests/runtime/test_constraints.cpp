// Constrained views (constraints.hpp) on hand-written models with closed forms.
#include "constrained_models.hpp"

#include "yamsc/constraints.hpp"
#include "yamsc/modal.hpp"
#include "yamsc/rk4.hpp"
#include "yamsc/simulation.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace yamsc::runtime;
using namespace test_constrained;

namespace {

std::vector<double> pendulum_state(const Pendulum& p, double th, double w) {
    return {p.L * std::sin(th), -p.L * std::cos(th), p.L * std::cos(th) * w,
            p.L * std::sin(th) * w};
}

/// Largest |a - b| relative to max(1, |b|) over two row-major matrices.
double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        d = std::max(d, std::fabs(a[i] - b[i]) / std::max(1.0, std::fabs(b[i])));
    return d;
}

/// Central differences of rhs in x.
std::vector<double> jacobian_by_differences(const ModelView& v, const std::vector<double>& x0,
                                            double t) {
    const std::size_t n = x0.size();
    std::vector<double> J(n * n), x = x0, p(n), m(n);
    for (std::size_t j = 0; j < n; ++j) {
        const double h = 1e-5 * std::max(1.0, std::fabs(x0[j]));
        x[j] = x0[j] + h;
        v.rhs(t, x.data(), nullptr, p.data());
        x[j] = x0[j] - h;
        v.rhs(t, x.data(), nullptr, m.data());
        x[j] = x0[j];
        for (std::size_t i = 0; i < n; ++i) J[i * n + j] = (p[i] - m[i]) / (2 * h);
    }
    return J;
}

std::size_t column(const SimulationResult& r, const std::string& name) {
    const auto it = std::find(r.columns.begin(), r.columns.end(), name);
    REQUIRE(it != r.columns.end());
    return static_cast<std::size_t>(it - r.columns.begin());
}

} // namespace

TEST_CASE("constrained: the Cartesian pendulum moves as the angle pendulum, with its tension") {
    const Pendulum p;
    const ModelView v = constrain(cartesian_pendulum(p));
    CHECK(v.ny == 1 + 1 + 1 + 1 + 2);
    CHECK(v.output_names[1] == "lambda:rod");
    CHECK(v.output_names[2] == "phi:rod");
    CHECK(v.output_names[3] == "r:rod");
    CHECK(v.output_names[4] == "constraint_position_error");
    const double th0 = 1.0, w0 = 0.5, dt = 5e-4, t_end = 2.0;
    SimulationOptions o;
    o.t_end = t_end;
    o.dt = dt;
    o.x0 = pendulum_state(p, th0, w0);
    const SimulationResult r = simulate(v, o);
    // The reference: the angle pendulum with RK4 at a step 8 times smaller.
    const OdeFunction angle = [&](double, const double* s, double* sd) {
        sd[0] = s[1];
        sd[1] = -p.g / p.L * std::sin(s[0]);
    };
    std::vector<double> s{th0, w0};
    const std::size_t lambda = column(r, "lambda:rod"), ydd = column(r, "ydd");
    double motion = 0, tension = 0;
    for (std::size_t row = 0; row < r.rows(); ++row) {
        if (row > 0)
            for (int k = 0; k < 8; ++k) rk4_step(angle, 0.0, dt / 8, s);
        const double* x = r.state_row(row);
        motion = std::max(motion, std::fabs(std::atan2(x[0], -x[1]) - s[0]));
        // The rod pulls with T = m (g cos th + L th'^2) = -2 L lambda.
        const double T = p.m * (p.g * std::cos(s[0]) + p.L * s[1] * s[1]);
        tension = std::max(tension, std::fabs(-2 * p.L * r.value(row, lambda) - T));
        // ydd is the constrained y'': the tension's vertical part minus gravity.
        const double y_dd = (T * std::cos(s[0])) / p.m - p.g;
        CHECK(r.value(row, ydd) == doctest::Approx(y_dd).epsilon(1e-9));
    }
    MESSAGE("pendulum: max |theta - theta_ref| = " << motion << ", tension error " << tension);
    CHECK(motion < 1e-10);
    CHECK(tension < 1e-10);
}

TEST_CASE("constrained: lin of the Cartesian pendulum in its independent coordinate") {
    const Pendulum p;
    const ModelView v = constrain(cartesian_pendulum(p));
    const ReducedLinearModel lin = reduced_linear_model(v, pendulum_state(p, 0, 0), {});
    REQUIRE(lin.n_coordinates == 1);
    CHECK(lin.state_names[0] == "x");
    CHECK(lin.choice.coordinates == std::vector<int>{1});
    REQUIRE(lin.modes.size() == 1);
    const double w = std::sqrt(p.g / p.L);
    CHECK(std::fabs(lin.modes[0].omega_n - w) < 1e-12 * w);
    CHECK(std::fabs(lin.modes[0].damping_ratio) < 1e-12);
    REQUIRE(lin.second_order);
    CHECK(lin.M[0] == doctest::Approx(p.m).epsilon(1e-14));
    CHECK(lin.K[0] == doctest::Approx(p.m * p.g / p.L).epsilon(1e-12));
    CHECK(std::fabs(lin.C[0]) < 1e-12);
    // The mode moves x only: y is second order in x at the bottom.
    CHECK(std::abs(lin.modes[0].shape[0] - 1.0) == 0.0);
    CHECK(std::abs(lin.modes[0].shape[1]) < 1e-14);
}

TEST_CASE("constrained: rhs_jacobian is exact (central differences agree)") {
    const Pendulum p;
    const ModelView pend = constrain(cartesian_pendulum(p));
    std::vector<double> x = pendulum_state(p, 0.7, -1.3);
    std::vector<double> J(16);
    pend.rhs_jacobian(0.0, x.data(), nullptr, J.data());
    const double dp = max_difference(J, jacobian_by_differences(pend, x, 0.0));
    for (bool exact : {true, false}) {
        const ModelView sleigh = constrain(chaplygin_sleigh(Sleigh{}, exact));
        const std::vector<double> xs{0.3, -0.2, 0.9, 0.8 * std::cos(0.9), 0.8 * std::sin(0.9), 1.7};
        std::vector<double> Js(36);
        sleigh.rhs_jacobian(0.0, xs.data(), nullptr, Js.data());
        const double ds = max_difference(Js, jacobian_by_differences(sleigh, xs, 0.0));
        MESSAGE("sleigh Jacobian vs differences (" << std::string(exact ? "exact" : "differenced")
                                                   << " d(Ma)/dq): " << ds);
        CHECK(ds < 1e-8);
    }
    MESSAGE("pendulum Jacobian vs differences: " << dp);
    CHECK(dp < 1e-8);
}

TEST_CASE("constrained: drift after 100 s stays below 1e-10 with the projection") {
    const Pendulum p;
    for (Method method : {Method::rk4, Method::abm4, Method::cvode}) {
        SimulationOptions o;
        o.t_end = 100;
        o.dt = method == Method::cvode ? 0.01 : 1e-3;
        o.dt_out = method == Method::cvode ? 0.0 : 0.01;
        o.method = method;
        o.rtol = 1e-10;
        o.atol = 1e-12;
        o.x0 = pendulum_state(p, 1.2, 0.3);
        double drift[2] = {0, 0};
        for (bool project : {true, false}) {
            ConstraintOptions co;
            co.project = project;
            const SimulationResult r = simulate(constrain(cartesian_pendulum(p), co), o);
            const double* x = r.state_row(r.rows() - 1);
            const ConstraintResiduals e =
                constraint_residual_norms(cartesian_pendulum(p), r.time.back(), x, nullptr);
            drift[project ? 0 : 1] = std::max(e.position, e.velocity);
        }
        MESSAGE(std::string(method_name(method)) << ": max residual after 100 s " << drift[0]
                                                 << " projected, " << drift[1] << " without");
        CHECK(drift[0] < 1e-10);
    }
}

TEST_CASE("constrained: the knife edge turns on its circle with the side force m v w") {
    Sleigh s;
    s.b = 0; // the centre of mass over the edge: torque-free, it turns at a constant rate
    const ModelView v = constrain(chaplygin_sleigh(s, true));
    const double speed = 1.5, w = 0.8, psi0 = 0.4;
    SimulationOptions o;
    o.t_end = 5;
    o.dt = 1e-3;
    o.dt_out = 0.1;
    o.x0 = {0, 0, psi0, speed * std::cos(psi0), speed * std::sin(psi0), w};
    const SimulationResult r = simulate(v, o);
    const std::size_t lambda = column(r, "lambda:edge");
    double path = 0, force = 0;
    for (std::size_t row = 0; row < r.rows(); ++row) {
        const double t = r.time[row], psi = psi0 + w * t, R = speed / w;
        const double* x = r.state_row(row);
        path = std::max({path, std::fabs(x[0] - R * (std::sin(psi) - std::sin(psi0))),
                         std::fabs(x[1] + R * (std::cos(psi) - std::cos(psi0))),
                         std::fabs(x[2] - psi)});
        force = std::max(force, std::fabs(r.value(row, lambda) - s.m * speed * w));
    }
    MESSAGE("knife edge: path error " << path << ", side force error " << force);
    CHECK(path < 1e-10);
    CHECK(force < 1e-10);
}

TEST_CASE("constrained: lin of the Chaplygin sleigh about straight motion") {
    const Sleigh s;
    const ModelView v = constrain(chaplygin_sleigh(s, false));
    const double speed = 1.2;
    const std::vector<double> x0{0, 0, 0, speed, 0, 0};
    const ReducedLinearModel lin = reduced_linear_model(v, x0, {});
    CHECK(lin.n_coordinates == 3);
    CHECK(lin.n_speeds == 2);
    CHECK(!lin.second_order);
    CHECK(lin.choice.speeds == std::vector<int>{1});
    // The yaw rate decays as w' = -m b v w / (I + m b^2); the rest is neutral.
    const double expected = -s.m * s.b * speed / (s.I + s.m * s.b * s.b);
    int dynamic = 0;
    for (const Mode& m : lin.modes) {
        if (m.rigid_body) continue;
        ++dynamic;
        CHECK(std::fabs(m.eigenvalue.real() - expected) < 1e-12 * std::fabs(expected));
        CHECK(m.eigenvalue.imag() == 0.0);
    }
    CHECK(dynamic == 1);
}

TEST_CASE("constrained: a prescribed angle's lambda is the holding torque") {
    const Prescribed p;
    const ModelView base = prescribed_pendulum(p);
    const ModelView v = constrain(base);
    // The start is made consistent: theta(0) = 0, theta'(0) = A w.
    const ConsistentState start = consistent_initial_state(base, 0.0, {0.3, 0.0}, {});
    CHECK(start.x[0] == doctest::Approx(0.0));
    CHECK(start.x[1] == doctest::Approx(p.A * p.w).epsilon(1e-15));
    CHECK(start.choice.named[0]);
    SimulationOptions o;
    o.t_end = 3;
    o.dt = 1e-3;
    o.dt_out = 0.05;
    o.x0 = start.x;
    const SimulationResult r = simulate(v, o);
    double torque = 0;
    for (std::size_t row = 0; row < r.rows(); ++row) {
        const double t = r.time[row];
        const double th = p.A * std::sin(p.w * t), thdd = -p.A * p.w * p.w * std::sin(p.w * t);
        const double tau = p.m * p.L * p.L * thdd + p.m * p.g * p.L * std::sin(th);
        torque = std::max(torque, std::fabs(r.value(row, column(r, "lambda:drive")) - tau));
        CHECK(std::fabs(r.state_row(row)[0] - th) < 1e-12);
    }
    MESSAGE("prescribed angle: holding torque error " << torque);
    CHECK(torque < 1e-10);
}

TEST_CASE("constrained: the consistent start and the trim of the Cartesian pendulum") {
    const Pendulum p;
    const ModelView base = cartesian_pendulum(p);
    // Off the circle and moving across it: y follows (x is independent there).
    const ConsistentState s = consistent_initial_state(base, 0.0, {0.3, -0.5, 0.2, 0.4}, {});
    CHECK(s.x[0] == 0.3);
    CHECK(s.x[1] == doctest::Approx(-std::sqrt(p.L * p.L - 0.09)).epsilon(1e-14));
    CHECK(std::fabs(0.3 * s.x[2] + s.x[1] * s.x[3]) < 1e-14);
    CHECK(describe_choice(base, s.choice).find("dependent coordinates: y\n") == 0);
    const ConstrainedTrimResult t = trim_constrained(constrain(base), {0.3, -0.5, 0, 0}, {});
    CHECK(t.converged);
    CHECK(std::fabs(t.x[0]) < 1e-12);
    CHECK(t.x[1] == doctest::Approx(-p.L).epsilon(1e-14));
}

TEST_CASE("constrained: redundant, inconsistent and singular rows are errors naming the row") {
    const Pendulum p;
    const std::vector<double> x0 = pendulum_state(p, 0.5, 0);
    SUBCASE("redundant") {
        ModelView v = cartesian_pendulum(p);
        const ModelView one = v;
        v.nh = v.nc = 2;
        v.constraint_names = {"rod", "copy"};
        v.constraint_dependent = {-1, -1};
        v.constraint_sources = {"m.mbd:3:1", "m.mbd:4:1"};
        v.constraint_matrix = [one](double t, const double* q, const double* u, double* B) {
            one.constraint_matrix(t, q, u, B);
            B[2] = 3 * B[0];
            B[3] = 3 * B[1];
        };
        try {
            consistent_initial_state(v, 0.0, x0, {});
            FAIL("no error");
        } catch (const ConstraintError& e) {
            CHECK(e.kind() == ConstraintErrorKind::redundant);
            CHECK(e.row() == 1);
            CHECK(e.related() == std::vector<int>{0});
            CHECK(std::string(e.what()).find("'copy' (m.mbd:4:1)") != std::string::npos);
            CHECK(std::string(e.what()).find("depends on 'rod' (m.mbd:3:1)") != std::string::npos);
        }
    }
    SUBCASE("inconsistent") {
        ModelView v = cartesian_pendulum(p);
        const ModelView one = v;
        // A second row x = 2 L: no point of the circle has it.
        v.nh = v.nc = 2;
        v.constraint_names = {"rod", "wall"};
        v.constraint_dependent = {-1, -1};
        v.constraint_sources = {"m.mbd:3:1", "m.mbd:4:1"};
        v.constraint_residuals = [one, p](double t, const double* q, const double* qd,
                                          const double* u, double* phi, double* r) {
            double f, g;
            one.constraint_residuals(t, q, qd, u, &f, &g);
            phi[0] = f;
            phi[1] = q[0] - 2 * p.L;
            r[0] = g;
            r[1] = qd[0];
        };
        v.constraint_matrix = [one](double t, const double* q, const double* u, double* B) {
            one.constraint_matrix(t, q, u, B);
            B[2] = 1;
            B[3] = 0;
        };
        try {
            consistent_initial_state(v, 0.0, x0, {});
            FAIL("no error");
        } catch (const ConstraintError& e) {
            CHECK(e.kind() == ConstraintErrorKind::inconsistent);
            CHECK(e.row() >= 0);
            CHECK(std::string(e.what()).find("cannot be satisfied") != std::string::npos);
        }
    }
    SUBCASE("singular: a named dependent DOF the row cannot be solved for") {
        ModelView v = cartesian_pendulum(p);
        v.constraint_dependent = {0}; // x, where the rod is vertical
        try {
            consistent_initial_state(v, 0.0, pendulum_state(p, 0, 0), {});
            FAIL("no error");
        } catch (const ConstraintError& e) {
            CHECK(e.kind() == ConstraintErrorKind::singular);
            CHECK(e.row() == 0);
            CHECK(std::string(e.what()).find("names 'x' dependent") != std::string::npos);
        }
    }
}
