// Morison loads of strip-theory members: viscous drag on a uniform relative
// velocity, the joints' axial drag, and the added-mass matrix of the OC3-Hywind
// spar against closed forms of its geometry.
#include "hydro_strip/oc3_spar.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace yamsc::runtime::hydro;
using namespace test;

TEST_CASE("drag on a uniform relative velocity: Cd rho D |v| v / 2 over the wet length") {
    const auto block = strip_theory_block(test::oc3_spar());
    const auto still = test::evaluate(*block, test::frame(at_rest, identity));
    // Projected area of the wet spar: the 9.4 m column, the taper, the 6.5 m column.
    const double projected = 9.4 * 108 + (9.4 + 6.5) / 2 * 8 + 6.5 * 4;
    for (double u : {0.7, -1.3}) {
        const double v[3] = {u, 0.5 * u, 0.2};
        const auto e = test::evaluate(*block, test::frame(at_rest, identity, v));
        // The water moves by -v relative to the spar; the axial part has no drag (AxCd 0).
        const double speed = std::hypot(v[0], v[1]);
        for (int i = 0; i < 2; ++i)
            CHECK(e.loads[static_cast<std::size_t>(i)] ==
                  doctest::Approx(-0.5 * test::cd * rho * projected * speed * v[i]).epsilon(1e-12));
        CHECK(e.loads[2] == doctest::Approx(still.loads[2]).epsilon(1e-14));
        // About the origin: the drag's centre is the projected area's centroid.
        const double first = 9.4 * 108 * -66 + 6.5 * 4 * -2 +
                             8 * (9.4 * (-12 + 8.0 / 3) + 6.5 * (-12 + 16.0 / 3)) / 2;
        // (trapezoids of D z over the taper's 0.5 m elements: 2e-6 of it)
        CHECK(e.loads[3] ==
              doctest::Approx(0.5 * test::cd * rho * first * speed * v[1]).epsilon(1e-5));
        CHECK(e.loads[4] ==
              doctest::Approx(-0.5 * test::cd * rho * first * speed * v[0]).epsilon(1e-5));
    }
}

TEST_CASE("a joint's axial drag on the flow through its end: AxCd rho A |v_n| v_n / 4") {
    StripSetup s = test::oc3_spar();
    s.members[0].joint1_axial.ax_cd = 1.0; // the keel
    const auto block = strip_theory_block(s);
    const auto still = test::evaluate(*block, test::frame(at_rest, identity));
    const double area = pi * 4.7 * 4.7;
    for (double w : {0.6, -0.9}) {
        const double v[3] = {0, 0, w};
        const auto e = test::evaluate(*block, test::frame(at_rest, identity, v));
        CHECK(e.loads[2] - still.loads[2] ==
              doctest::Approx(-0.25 * rho * area * std::abs(w) * w).epsilon(1e-9));
    }
}

TEST_CASE("the OC3 spar's added mass: Ca rho V in surge and sway, symmetric, about the origin") {
    const auto block = strip_theory_block(test::oc3_spar());
    CHECK(block->has_added_mass());
    double A[36];
    block->added_mass(0, nullptr, nullptr, A);
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < i; ++j)
            CHECK(A[6 * i + j] == doctest::Approx(A[6 * j + i]).epsilon(1e-12).scale(1));
    // Exactly: Ca rho pi sum R_n^2 dl_n; the taper's R^2 is summed by the trapezoid
    // rule over 0.5 m elements, (dR/dl)^2 dl^2 L / 6 above its exact integral.
    const double taper = (4.7 - 3.25) / 8;
    const double v = test::oc3_volume() + pi * taper * taper * 0.25 * 8 / 6;
    CHECK(A[0] == doctest::Approx(test::ca * rho * v).epsilon(1e-12));
    CHECK(A[7] == doctest::Approx(test::ca * rho * v).epsilon(1e-12));
    CHECK(A[0] == doctest::Approx(test::ca * rho * test::oc3_volume()).epsilon(1e-5));
    // 7.98e6 kg with the definition's Ca = 0.969954 (rho V = 8.23e6 kg).
    CHECK(A[0] == doctest::Approx(7.9827e6).epsilon(1e-4));
    // Surge-pitch coupling: the first moment of the same masses about the origin.
    const double z_b = test::oc3_buoyancy_centre();
    CHECK(A[4] == doctest::Approx(test::ca * rho * test::oc3_volume() * z_b).epsilon(1e-4));
    CHECK(A[4] < 0);
    CHECK(A[6 * 4] == doctest::Approx(A[4]));
    // Heave: only the taper's axial term (AxCa 1) and no end effect (the joints' AxCa 0).
    const double heave =
        2 * rho * pi * taper *
        (8 * (4.7 * 4.7 + 4.7 * 3.25 + 3.25 * 3.25) / 3 + taper * taper * 0.25 * 8 / 6);
    CHECK(A[14] == doctest::Approx(heave).epsilon(1e-3));
    CHECK(A[35] == doctest::Approx(0.0).scale(1));
}

TEST_CASE("Morison inertia on a vertical cylinder in an Airy wave, and Froude-Krylov on its keel") {
    // A 6 m column 40 m deep in 320 m of water, held still; no drag.
    StripSetup s = test::oc3_spar(0.1);
    s.members.resize(1);
    s.members[0].end1 = {0, 0, -40};
    s.members[0].end2 = {0, 0, 10};
    s.members[0].diameter1 = s.members[0].diameter2 = 6;
    s.members[0].c1 = s.members[0].c2 = {0, test::ca, 1.0, 0, 1.0, 1.0};
    s.members[0].joint1_axial = {0, 0, 0, 0, 0, 1.0}; // AxCp 1 at the keel
    WaveSettings w;
    w.kind = WaveKind::regular;
    w.water = s.water;
    w.height = 6;
    w.period = 10; // on the 600 s grid
    w.t_max = 600;
    w.phase = 0.4;
    s.waves = make_wave_field(w);
    const auto block = strip_theory_block(s);
    const double omega = 2 * pi / 10, h = 320, a = 3, r = 3;
    const double k = wave_number(omega, g, h);
    for (double t : {0.0, 2.5, 6.25}) {
        const auto e = test::evaluate(*block, test::frame(at_rest, identity), t);
        const double theta = omega * t + 0.4;
        // (Ca + Cp) rho pi r^2 times the integral of the acceleration over the depth.
        const double integral = (std::sinh(k * h) - std::sinh(k * (h - 40))) / k;
        const double fx = -(test::ca + 1) * rho * pi * r * r * a * omega * omega * std::sin(theta) *
                          integral / std::sinh(k * h);
        CHECK(e.loads[0] == doctest::Approx(fx).epsilon(1e-5));
        CHECK(std::abs(e.loads[1]) < 1e-6 * std::abs(fx) + 1e-9);
        // Vertical: buoyancy and the wave's dynamic pressure on the keel's area.
        const double keel =
            rho * g * a * std::cosh(k * (h - 40)) / std::cosh(k * h) * std::cos(theta);
        CHECK(e.loads[2] ==
              doctest::Approx(rho * g * pi * r * r * 40 + pi * r * r * keel).epsilon(1e-9));
    }
}

TEST_CASE("the flow tabulated at the undisplaced strips is the field's, displaced kinematics at "
          "rest alike; a turning spar's added mass pulls outwards") {
    StripSetup s = test::oc3_spar();
    WaveSettings w;
    w.kind = WaveKind::irregular;
    w.water = s.water;
    w.height = 6;
    w.period = 10;
    w.t_max = 600;
    w.dt = 0.25;
    w.low_cutoff = 0.1;
    w.high_cutoff = 3;
    w.seed1 = 7;
    s.waves = make_wave_field(w);
    const auto fixed = strip_theory_block(s);
    s.kinematics_displaced = true;
    const auto moving = strip_theory_block(s);
    const auto frame = test::frame(at_rest, identity);
    for (double t : {10.0, 33.25}) { // on the field's time grid
        const auto a = test::evaluate(*fixed, frame, t), b = test::evaluate(*moving, frame, t);
        CHECK(std::abs(a.loads[0]) > 1e4);
        for (std::size_t i = 0; i < 6; ++i)
            CHECK(a.loads[i] == doctest::Approx(b.loads[i]).epsilon(1e-9).scale(1e-3));
    }
    // A yaw rate about a vertical axis 10 m off the spar's: the strips accelerate
    // towards that axis by w^2 * 10 m, so their added mass pushes the spar away.
    StripSetup still = test::oc3_spar();
    still.origin_at_rest = {-10, 0, 0};
    for (StripMember& m : still.members) m.c1.cd = m.c2.cd = 0; // its speed, 2 m/s, drags
    const auto turning = strip_theory_block(still);
    const double origin[3] = {-10, 0, 0}, yaw[3] = {0, 0, 0.2};
    const auto e = test::evaluate(*turning, test::frame(origin, identity, nullptr, yaw));
    double A[36];
    turning->added_mass(0, nullptr, nullptr, A);
    CHECK(e.loads[0] == doctest::Approx(A[0] * 0.04 * 10).epsilon(1e-12));
    CHECK(std::abs(e.loads[1]) < 1e-6);
}
