// Reaction loads (reaction_force, reaction_moment) against Newton-Euler by hand:
// the double pendulum's pins link by link at random states, a rigid tower's
// base at an equilibrium and in motion, a flexible cantilever's root at its
// static deflection and in motion. The generated `outputs` solve M q'' = F.
#include "equations_fixture.hpp"
#include "solved_state.hpp"

#include "driver/commands.hpp"

#include <Eigen/Dense>

#include <sstream>

using namespace yamsc;

namespace {

using physics_test::at;
using physics_test::State;

int index_of(const runtime::ModelView& v, const std::string& name) {
    for (std::size_t i = 0; i < v.output_names.size(); ++i)
        if (v.output_names[i] == name) return static_cast<int>(i);
    FAIL("no output " << name);
    return -1;
}

using physics_test::equilibrium;

} // namespace

TEST_CASE("reactions: double pendulum pins = m a - external loads, link by link") {
    auto eq = test::derive_file("tests/physics/models/reactions_double_pendulum.mbd");
    auto c = test::compile_model(eq);
    const runtime::ModelView& v = c.view;
    const double m1 = 2.0, m2 = 1.0, L1 = 1.0, L2 = 0.8, g = 9.81, k = 5.0, damping = 0.1;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(-2.5, 2.5);
    double worst = 0;
    for (int trial = 0; trial < 20; ++trial) {
        const std::vector<double> q{U(rng), U(rng)}, qd{U(rng), U(rng)}, u{U(rng), U(rng)};
        const State s = at(v, q, qd, u);
        auto y = [&](const char* name) { return s.y[static_cast<std::size_t>(index_of(v, name))]; };
        const double f = u[1];
        const double p1 = q[0], p2 = q[0] + q[1], w1 = qd[0], w2 = qd[0] + qd[1];
        const double a1 = s.qdd[0], a2 = s.qdd[0] + s.qdd[1];
        // Point masses at the link ends (ground x, z); rotate y by p: (x, z) = -L (sin p, cos p).
        const double x1 = -L1 * std::sin(p1), z1 = -L1 * std::cos(p1);
        const double x2 = x1 - L2 * std::sin(p2), z2 = z1 - L2 * std::cos(p2);
        const double ax1 = -L1 * (std::cos(p1) * a1 - std::sin(p1) * w1 * w1);
        const double az1 = L1 * (std::sin(p1) * a1 + std::cos(p1) * w1 * w1);
        const double ax2 = ax1 - L2 * (std::cos(p2) * a2 - std::sin(p2) * w2 * w2);
        const double az2 = az1 + L2 * (std::sin(p2) * a2 + std::cos(p2) * w2 * w2);
        // link2: m2 a2 = R2 + m2 G + f; link1: m1 a1 = R1 + m1 G - R2.
        const double R2x = m2 * ax2 - f, R2z = m2 * az2 + m2 * g;
        const double R1x = m1 * ax1 + R2x, R1z = m1 * az1 + m1 * g + R2z;
        // About the elbow: (p2 - p1) x (m2 a2 - m2 G - f), y component r_z F_x - r_x F_z.
        const double M2 = (z2 - z1) * R2x - (x2 - x1) * R2z;
        const double scale = 1 + std::fabs(R1x) + std::fabs(R1z);
        const double errors[] = {
            y("F1x") - R1x,
            y("F1y"),
            y("F1z") - R1z,
            y("M1y"), // the pin transmits no moment about its axis
            y("F2x") - R2x,
            y("F2z") - R2z,
            y("M2y") - M2,
            y("M2y") - (-k * q[1] - damping * qd[1]), // the elbow spring, and only it
            y("M2x"),
            y("F2a") - (R2x * std::sin(p2) + R2z * std::cos(p2)),
            y("acc1") - s.qdd[0],
            y("acc2") - s.qdd[1],
        };
        for (double e : errors) worst = std::max(worst, std::fabs(e) / scale);
    }
    MESSAGE("double pendulum: worst |reaction - Newton-Euler| / load " << worst);
    CHECK(worst < 1e-12);
}

TEST_CASE("reactions: rigid tower with a top mass, static base loads and in motion") {
    auto eq = test::derive_file("tests/physics/models/reactions_rigid_tower.mbd");
    const double g = 9.81, L = 20, m_t = 6000, M = 2e4, x_G = 1.5, y_G = 0.5, z_G = 2;
    // The spring that makes tilt0 an equilibrium: K tilt0 = the weights' moment.
    const double tilt0 = 0.05, h = L + z_G;
    const double x_top = x_G * std::cos(tilt0) + h * std::sin(tilt0);
    const double weight_moment = g * (m_t * L / 2 * std::sin(tilt0) + M * x_top);
    const double K = weight_moment / tilt0;
    auto c = test::compile_model(eq, {{"K", K}});
    const runtime::ModelView& v = c.view;
    auto y = [&](const State& s, const char* name) {
        return s.y[static_cast<std::size_t>(index_of(v, name))];
    };
    const State rest = at(v, {tilt0}, {0.0});
    CHECK(std::fabs(rest.qdd[0]) < 1e-12);
    CHECK(y(rest, "x_top") == doctest::Approx(x_top).epsilon(1e-14));
    const double W = (m_t + M) * g;
    MESSAGE("rigid tower at rest: base My " << y(rest, "My") << " N m (static " << -weight_moment
                                            << "), Mx " << y(rest, "Mx"));
    CHECK(std::fabs(y(rest, "Fx")) < 1e-9 * W);
    CHECK(std::fabs(y(rest, "Fy")) < 1e-9 * W);
    CHECK(y(rest, "Fz") == doctest::Approx(W).epsilon(1e-13));
    CHECK(y(rest, "My") == doctest::Approx(-weight_moment).epsilon(1e-12));
    CHECK(y(rest, "Mx") == doctest::Approx(M * g * y_G).epsilon(1e-12));
    CHECK(std::fabs(y(rest, "Mz")) < 1e-9 * weight_moment);
    // In the tower's axes (turned about y): Mx_t = Mx cos + Mz sin = Mx cos(tilt0).
    CHECK(y(rest, "Mx_t") == doctest::Approx(M * g * y_G * std::cos(tilt0)).epsilon(1e-12));

    // In motion: the force is Σ m a_G - Σ m G, the moment about the pin axis the spring's.
    const double tilt = -0.2, rate = 0.7;
    const State s = at(v, {tilt}, {rate});
    const double a = s.qdd[0], cs = std::cos(tilt), sn = std::sin(tilt);
    const double xt = L / 2 * sn, zt = L / 2 * cs;
    const double xm = x_G * cs + h * sn, zm = -x_G * sn + h * cs;
    // A point (x, z) turning about y: a = (z a - x w^2, -x a - z w^2).
    const double Fx = m_t * (zt * a - xt * rate * rate) + M * (zm * a - xm * rate * rate);
    const double Fz = m_t * (-xt * a - zt * rate * rate) + M * (-xm * a - zm * rate * rate) + W;
    CHECK(y(s, "Fx") == doctest::Approx(Fx).epsilon(1e-12));
    CHECK(std::fabs(y(s, "Fy")) < 1e-9 * W);
    CHECK(y(s, "Fz") == doctest::Approx(Fz).epsilon(1e-12));
    CHECK(y(s, "My") == doctest::Approx(-K * tilt).epsilon(1e-12));
}

TEST_CASE("reactions: flexible cantilever root loads at its static deflection and in motion") {
    auto eq = test::derive_file("tests/physics/models/reactions_cantilever.mbd");
    auto c = test::compile_model(eq);
    const runtime::ModelView& v = c.view;
    auto y = [&](const State& s, const char* name) {
        return s.y[static_cast<std::size_t>(index_of(v, name))];
    };
    const double g = 9.81, L = 20, m = 300, M = 2e3;
    // The beam's shape z^2 (tip deflection q): ∫ Φ dm = m L / 3 and its axial
    // shortening ∫ w dm = m q^2 / 6 (K_gt = -m/3, tests/physics/models/tower_top_mass.mbd).
    const double Ct = m * L / 3, Ct1 = -m / 3;
    const std::vector<double> q = equilibrium(v, {0.0});
    const State rest = at(v, q, {0.0});
    CHECK(std::fabs(rest.qdd[0]) < 1e-9);
    // Root moment = -(∫ m g x dz + M g x_tip), x along the beam, less its shortening.
    const double integral = g * (m * L * L / 2 + Ct1 * q[0] * q[0] / 2);
    const double expected = -(integral + M * g * y(rest, "x_tip"));
    MESSAGE("cantilever: static tip deflection " << q[0] << " m, root moment " << y(rest, "My")
                                                 << " N m, relative difference to the integral "
                                                 << (y(rest, "My") - expected) / expected);
    CHECK(q[0] > 0.01); // bent downward (along the mode) by its weight
    CHECK(y(rest, "My") == doctest::Approx(expected).epsilon(1e-13));
    CHECK(y(rest, "Fz") == doctest::Approx((m * L + M) * g).epsilon(1e-12));
    CHECK(std::fabs(y(rest, "Fx")) < 1e-9 * M * g);
    CHECK(y(rest, "Tz") == doctest::Approx(M * g).epsilon(1e-12));
    CHECK(std::fabs(y(rest, "Mx")) < 1e-9 * std::fabs(expected));

    // In motion: the root force is the momentum rate of beam and tip minus their
    // weight. The beam's mass centre moves with md(q) = (Ct q, 0, m L^2/2 + Ct1 q^2/2)
    // in body axes, ground (x, z) = (md_z, -md_x); the tip's acceleration is
    // ∂v/∂q q' + ∂v/∂q' q'' (central differences of its velocity outputs).
    const double qq = 0.4, qd = -1.3;
    const State s = at(v, {qq}, {qd});
    const double a = s.qdd[0];
    auto tip_acceleration = [&](const char* vname) {
        const double hq = 1e-6;
        const double dv_dq =
            (y(at(v, {qq + hq}, {qd}), vname) - y(at(v, {qq - hq}, {qd}), vname)) / (2 * hq);
        const double dv_dqd =
            (y(at(v, {qq}, {qd + hq}), vname) - y(at(v, {qq}, {qd - hq}), vname)) / (2 * hq);
        return dv_dq * qd + dv_dqd * a;
    };
    const double Fx = Ct1 * (qq * a + qd * qd) + M * tip_acceleration("vx_tip");
    const double Fz = -Ct * a + M * tip_acceleration("vz_tip") + (m * L + M) * g;
    MESSAGE("cantilever in motion: root force ("
            << y(s, "Fx") << ", " << y(s, "Fz") << ") N, relative differences to the momentum rate "
            << (y(s, "Fx") - Fx) / Fx << ", " << (y(s, "Fz") - Fz) / Fz);
    CHECK(y(s, "Fx") == doctest::Approx(Fx).epsilon(1e-8)); // central differences: 4e-11
    CHECK(y(s, "Fz") == doctest::Approx(Fz).epsilon(1e-8));
}

TEST_CASE("reactions: `yamsc eval` solves q'' for them as the generated outputs do") {
    const std::string model =
        test::source_path("tests/physics/models/reactions_double_pendulum.mbd");
    auto eq = test::derive_file("tests/physics/models/reactions_double_pendulum.mbd");
    auto c = test::compile_model(eq);
    const std::vector<double> q{0.3, 0.2}, qd{0.5, -0.4}, u{1.5, 2.0};
    const State s = at(c.view, q, qd, u);
    driver::EvalOptions o;
    o.model = model;
    o.q = q;
    o.qd = qd;
    o.u = {{"tau", 0, u[0]}, {"f", 0, u[1]}};
    std::ostringstream out, err;
    REQUIRE(driver::eval(o, out, err) == 0);
    const std::string text = out.str();
    const auto start = text.find("\"y\":[");
    REQUIRE(start != std::string::npos);
    std::istringstream values(text.substr(start + 5));
    double worst = 0;
    for (std::size_t i = 0; i < s.y.size(); ++i) {
        double y = 0;
        char sep = 0;
        values >> y >> sep;
        worst = std::max(worst, std::fabs(y - s.y[i]) / (1 + std::fabs(s.y[i])));
    }
    MESSAGE("eval vs generated outputs: worst relative difference " << worst);
    CHECK(worst < 1e-13);
}

TEST_CASE("reactions: a free-floating flexible beam's joint transmits nothing along its free "
          "directions") {
    // Kane's equation of each free direction says the subtree's momentum rate
    // there equals the applied loads: the flexible body's momentum rate from its
    // shape integrals (Coriolis, centrifugal, elastic accelerations, a body on
    // its tip node) must make the reactions vanish at any state.
    auto eq = test::derive_file("tests/physics/models/reactions_free_beam.mbd");
    auto c = test::compile_model(eq);
    const runtime::ModelView& v = c.view;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(-1, 1);
    const double weight = (40 * 50 + 20 + 300) * 9.81;
    double worst = 0, held = 0;
    for (int trial = 0; trial < 10; ++trial) {
        std::vector<double> q(7), qd(7);
        for (double& x : q) x = U(rng);
        for (double& x : qd) x = 2 * U(rng);
        const State s = at(v, q, qd);
        auto y = [&](const char* name) { return s.y[static_cast<std::size_t>(index_of(v, name))]; };
        for (const char* name : {"Fx", "Fy", "Fz"})
            worst = std::max(worst, std::fabs(y(name)) / weight);
        for (const char* name : {"Mx", "My_bar"})
            worst = std::max(worst, std::fabs(y(name)) / (weight * 40));
        held = std::max(held, std::fabs(y("Mz_bar")));
    }
    MESSAGE("free-floating beam: worst free-direction reaction / weight "
            << worst << "; held moment up to " << held << " N m");
    CHECK(worst < 1e-13);
    CHECK(held > 1.0); // the joint does hold the third rotation
}
