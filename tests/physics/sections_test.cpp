// Loads through a section of a flexible body (reaction_force/reaction_moment of
// `bar.node(k)`, `bar.tip`) against Newton-Euler by hand: a cantilever's mid-span
// moment at its static deflection against the integral of the weights beyond the
// cut, the lumped (ElastoDyn) discretization against its element sums, and a
// free-floating beam in motion, whose root and tip sections must transmit what
// the joints there do. The generated `outputs` solve M q'' = F.
#include "equations_fixture.hpp"
#include "solved_state.hpp"

#include <Eigen/Dense>

#include <random>

using namespace yamsc;

namespace {

using physics_test::at;
using physics_test::State;

double output(const runtime::ModelView& v, const State& s, const std::string& name) {
    for (std::size_t i = 0; i < v.output_names.size(); ++i)
        if (v.output_names[i] == name) return s.y[i];
    FAIL("no output " << name);
    return 0;
}

} // namespace

TEST_CASE("sections: a cantilever's mid-span moment is that of the weights beyond the cut") {
    auto eq = test::derive_file("tests/physics/models/sections_cantilever.mbd");
    auto c = test::compile_model(eq);
    const runtime::ModelView& v = c.view;
    const double g = 9.81, L = 20, m = 300, M = 2e3, s = 10; // node 3 at z = 10
    const double q = physics_test::equilibrium(v, {0.0})[0];
    const State rest = at(v, {q}, {0.0});
    auto y = [&](const char* name) { return output(v, rest, name); };
    REQUIRE(std::fabs(rest.qdd[0]) < 1e-9);
    REQUIRE(q > 0.01);
    // Shape (z/L)^2; a point at z shortens along the beam by q^2 S(z) / 2 with
    // S(z) = -∫ Φ'^2 = -4 z^3 / (3 L^4). The beam lies along ground x and bends
    // down: the weights beyond the cut turn about the deformed node P with arms
    // x(z) - x_P = z - s + q^2 (S(z) - S(s)) / 2.
    auto S = [&](double z) { return -4 * z * z * z / (3 * L * L * L * L); };
    const double int_S = -(std::pow(L, 4) - std::pow(s, 4)) / (3 * std::pow(L, 4)); // ∫_s^L S
    const double x_P = s + q * q * S(s) / 2;
    const double beam = g * m * ((L - s) * (L - s) / 2 + q * q / 2 * (int_S - (L - s) * S(s)));
    const double expected = -(beam + M * g * (y("x_tip") - x_P)); // inboard on outboard
    MESSAGE("cantilever: tip deflection " << q << " m; mid-span moment " << y("My3")
                                          << " N m, relative difference to the integral "
                                          << (y("My3") - expected) / expected);
    CHECK(y("My3") == doctest::Approx(expected).epsilon(1e-12));
    CHECK(y("My3_bar") == doctest::Approx(expected).epsilon(1e-12)); // bar's y is ground y
    CHECK(y("Fz3") == doctest::Approx((m * (L - s) + M) * g).epsilon(1e-12));
    // In the deformed section's axes: the body's turned about y by the slope 2 s q / L^2
    // (body x is ground -z, body z ground x).
    const double th = 2 * s * q / (L * L), Fbx = -y("Fz3"), Fbz = y("Fx3");
    CHECK(y("My3_node") == doctest::Approx(expected).epsilon(1e-12));
    CHECK(y("Fx3_node") == doctest::Approx(std::cos(th) * Fbx - std::sin(th) * Fbz).epsilon(1e-12));
    CHECK(y("Fz3_node") == doctest::Approx(std::sin(th) * Fbx + std::cos(th) * Fbz).epsilon(1e-12));
    CHECK(y("x_tip_node") == doctest::Approx(1.0).epsilon(1e-14)); // z_G in the tip's axes
    // The root node is the body's root joint, the tip node the tip body's joint.
    for (auto [a, b] : {std::pair{"My1", "My"}, {"Fx1", "Fx"}, {"Fz1", "Fz"}}) {
        CAPTURE(a);
        CHECK(y(a) == doctest::Approx(y(b)).epsilon(1e-12));
    }
    CHECK(y("Mtip") == doctest::Approx(y("Mt")).epsilon(1e-12));
    CHECK(y("Ftip") == doctest::Approx(y("Ft")).epsilon(1e-12));
}

TEST_CASE("sections: ElastoDyn's lumped beam, half the gauge element beyond the cut") {
    auto eq = test::derive_file("tests/physics/models/sections_lumped.mbd");
    auto c = test::compile_model(eq);
    const runtime::ModelView& v = c.view;
    const double g = 9.81, L = 20, m = 300;
    const int N = 4;
    const double dr = L / N;
    // The discretization's shape: (z/L)^2's curvature 2/L^2 integrated twice by
    // ElastoDyn's midpoint running sums over root, element centres and tip.
    std::vector<double> z{0}, w{0};
    for (int j = 0; j < N; ++j) {
        z.push_back((j + 0.5) * dr);
        w.push_back(dr);
    }
    z.push_back(L);
    w.push_back(0);
    std::vector<double> slope(z.size(), 0.0), phi(z.size(), 0.0);
    const double curvature = 2 / (L * L);
    for (std::size_t i = 1; i < z.size(); ++i)
        slope[i] = slope[i - 1] + 0.5 * (w[i - 1] + w[i]) * curvature;
    for (std::size_t i = 1; i < z.size(); ++i)
        phi[i] = phi[i - 1] + 0.5 * w[i - 1] * slope[i - 1] + 0.5 * w[i] * slope[i];
    // Undeformed and at rest, the elements accelerate along body x (down) by
    // Φ q'' under g; the section at centre k carries the elements beyond it and
    // half its own, a quarter element beyond the node.
    const State s = at(v, {0.0}, {0.0});
    const double a = s.qdd[0];
    for (std::size_t k : {1u, 3u}) { // SID nodes 2 and 4
        double F = 0, My = 0;
        for (std::size_t j = k + 1; j <= static_cast<std::size_t>(N); ++j) {
            const double f = m * dr * (g - phi[j] * a);
            F += f;
            My += (z[j] - z[k]) * f; // (0, 0, Δz) × (f, 0, 0) = (0, Δz f, 0)
        }
        const double half = 0.5 * m * dr * (g - phi[k] * a);
        F += half;
        My += 0.25 * dr * half;
        const std::string id = std::to_string(k + 1);
        CAPTURE(id);
        MESSAGE("lumped beam, node " << id << ": moment " << output(v, s, "My" + id)
                                     << " N m, element sum " << -My);
        CHECK(output(v, s, "Fx" + id) == doctest::Approx(-F).epsilon(1e-12));
        CHECK(output(v, s, "My" + id) == doctest::Approx(-My).epsilon(1e-12));
    }
}

TEST_CASE("sections: a spinning beam's sections carry the centripetal and tangential loads") {
    auto eq = test::derive_file("tests/physics/models/sections_spinning.mbd");
    auto c = test::compile_model(eq);
    const runtime::ModelView& v = c.view;
    const double L = 20, m = 300, T = 1e5, Omega = 1.3;
    const State s = at(v, {0.4, 0.0}, {Omega, 0.0});
    auto y = [&](const std::string& name) { return output(v, s, name); };
    // Undeformed, the beam turns as a rigid rod: I = m L^3 / 3, no bending.
    const double alpha = T / (m * L * L * L / 3);
    CHECK(s.qdd[0] == doctest::Approx(alpha).epsilon(1e-12));
    CHECK(std::fabs(s.qdd[1]) < 1e-12);
    // Beyond z = s the mass accelerates by (tangential α z, radial -Ω² z): the
    // inboard part pulls it in and pushes it along; the moment about body x of the
    // tangential force, e_z × e_y = -e_x.
    for (const auto& [node, z0] : {std::pair{"2", 5.0}, {"4", 15.0}}) {
        CAPTURE(node);
        const double radial = -m * Omega * Omega * (L * L - z0 * z0) / 2;
        const double tangential = m * alpha * (L * L - z0 * z0) / 2;
        const double moment =
            -m * alpha * ((L * L * L - z0 * z0 * z0) / 3 - z0 * (L * L - z0 * z0) / 2);
        CHECK(y(std::string("Fz") + node) == doctest::Approx(radial).epsilon(1e-12));
        CHECK(y(std::string("Fy") + node) == doctest::Approx(tangential).epsilon(1e-12));
        CHECK(y(std::string("Mx") + node) == doctest::Approx(moment).epsilon(1e-12));
    }
    CHECK(std::fabs(y("Fx2")) < 1e-9);
    // The torque on the frame acts at the root: the root node's section is the joint's.
    CHECK(y("Mx1") == doctest::Approx(y("Mx_root")).epsilon(1e-12));
    MESSAGE("spinning beam: section at z = 5: radial " << y("Fz2") << " N, tangential " << y("Fy2")
                                                       << " N, moment " << y("Mx2") << " N m");
}

TEST_CASE("sections: a free-floating beam in motion, root and tip sections equal the joints'") {
    auto eq = test::derive_file("tests/physics/models/sections_free_beam.mbd");
    auto c = test::compile_model(eq);
    const runtime::ModelView& v = c.view;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-1, 1);
    double worst_root = 0, worst_tip = 0, mid = 0;
    for (int trial = 0; trial < 10; ++trial) {
        std::vector<double> q(7), qd(7);
        for (double& x : q) x = U(rng);
        for (double& x : qd) x = 2 * U(rng);
        const State s = at(v, q, qd);
        auto y = [&](const std::string& name) { return output(v, s, name); };
        double scale_root = 1, scale_tip = 1;
        for (const char* k : {"Fx", "Fy", "Fz"}) scale_root = std::max(scale_root, std::fabs(y(k)));
        for (const char* k : {"Ftx", "Fty", "Ftz"})
            scale_tip = std::max(scale_tip, std::fabs(y(k)));
        for (const std::string k : {"Fx", "Fy", "Fz"})
            worst_root = std::max(worst_root, std::fabs(y(k + "_root") - y(k)) / scale_root);
        for (const std::string k : {"Mx", "My", "Mz"})
            worst_root = std::max(worst_root, std::fabs(y(k + "_root") - y(k)) / (40 * scale_root));
        for (const std::string k : {"Ftx", "Fty", "Ftz"})
            worst_tip = std::max(worst_tip, std::fabs(y(k + "_cut") - y(k)) / scale_tip);
        for (const std::string k : {"Mtx", "Mty", "Mtz"})
            worst_tip = std::max(worst_tip, std::fabs(y(k + "_cut") - y(k)) / scale_tip);
        mid = std::max(mid, std::fabs(y("My_mid")));
    }
    MESSAGE("free-floating beam: worst |root section - root reaction| / load "
            << worst_root << ", tip " << worst_tip << "; mid-span moment up to " << mid << " N m");
    CHECK(worst_root < 1e-12);
    CHECK(worst_tip < 1e-12);
    CHECK(mid > 1.0);
}
