// Buoyancy of strip-theory members: the OC3-Hywind spar's displaced volume and
// hydrostatic restoring against closed forms from its geometry, and members cut
// obliquely by the still-water plane in large rotations against an independent
// integration of the submerged volume slice by slice.
#include "hydro_strip/oc3_spar.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>

using namespace yamsc::runtime::hydro;
using namespace test;

namespace {

// Volume below z = 0 of the frustum from a (radius ra) to b (radius rb) and its
// first moment, by slices across the axis: each slice's wetted part is a circular
// segment, whose area and centroid are closed forms.
struct Slices {
    double volume = 0;
    std::array<double, 3> moment{};
};
Slices slice_integral(const double a[3], const double b[3], double ra, double rb) {
    double k[3], length = 0;
    for (int i = 0; i < 3; ++i) length += (b[i] - a[i]) * (b[i] - a[i]);
    length = std::sqrt(length);
    for (int i = 0; i < 3; ++i) k[i] = (b[i] - a[i]) / length;
    // e: the direction in the slice's plane that rises fastest, |e_z - (k.e_z) k| = sin.
    double e[3] = {-k[2] * k[0], -k[2] * k[1], 1 - k[2] * k[2]};
    const double sin_g = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    for (double& x : e) x /= sin_g;
    Slices out;
    const int n = 400000;
    const double ds = length / n;
    for (int j = 0; j < n; ++j) {
        const double s = (j + 0.5) * ds;
        const double r = ra + (rb - ra) * s / length;
        double c[3];
        for (int i = 0; i < 3; ++i) c[i] = a[i] + s * k[i];
        const double d = std::max(-r, std::min(r, -c[2] / sin_g)); // wet: x <= d
        const double h = std::sqrt(r * r - d * d);
        const double area = r * r * (pi - std::acos(d / r)) + d * h;
        const double first = -2.0 / 3.0 * h * h * h; // integral of x over the wet part
        out.volume += area * ds;
        for (int i = 0; i < 3; ++i) out.moment[i] += (area * c[i] + first * e[i]) * ds;
    }
    return out;
}

StripSetup one_member(const double a[3], const double b[3], double da, double db) {
    StripSetup s = test::oc3_spar();
    s.members.resize(1);
    s.members[0].end1 = {a[0], a[1], a[2]};
    s.members[0].end2 = {b[0], b[1], b[2]};
    s.members[0].diameter1 = da;
    s.members[0].diameter2 = db;
    return s;
}

} // namespace

TEST_CASE("the OC3 spar at rest: buoyancy rho g V of its submerged volume, upright") {
    const double v = test::oc3_volume();
    CHECK(v == doctest::Approx(8029.21).epsilon(1e-6)); // HydroDyn's PtfmVol0 for the deck
    const auto block = strip_theory_block(test::oc3_spar());
    const auto e = test::evaluate(*block, test::frame(at_rest, identity));
    CHECK(e.loads[2] == doctest::Approx(rho * g * v).epsilon(1e-12));
    for (int i : {0, 1, 3, 4, 5}) CHECK(std::abs(e.loads[static_cast<std::size_t>(i)]) < 1e-6);
    CHECK(e.out[6] == doctest::Approx(v).epsilon(1e-12));
    CHECK(block->output_names()[0] == "strip_Fxi");
}

TEST_CASE("the OC3 spar's hydrostatic restoring from central differences of the block's loads") {
    const auto block = strip_theory_block(test::oc3_spar());
    const double h = 1e-4;
    // Heave: the waterplane area of the 6.5 m column.
    const double up[3] = {0, 0, h}, down[3] = {0, 0, -h};
    const double c33 = -(test::evaluate(*block, test::frame(up, identity)).loads[2] -
                         test::evaluate(*block, test::frame(down, identity)).loads[2]) /
                       (2 * h);
    const double waterplane = pi * 3.25 * 3.25;
    CHECK(c33 == doctest::Approx(rho * g * waterplane).epsilon(1e-9));
    // The OC3 report's 332,941 N/m is 0.18 % below rho g A_wp = 333,552 N/m (its
    // value comes from WAMIT's panel model of the spar, not from the circle).
    CHECK(c33 == doctest::Approx(332941).epsilon(2.5e-3));
    // Roll and pitch: rho g (V z_B + I_wp), z_B < 0; yaw: none.
    const double expected =
        rho * g * (test::oc3_volume() * test::oc3_buoyancy_centre() + pi * std::pow(3.25, 4) / 4);
    for (int axis = 0; axis < 2; ++axis) {
        double u[3] = {0, 0, 0};
        u[axis] = 1;
        double Rp[9], Rm[9];
        test::rotation(u, h, Rp);
        test::rotation(u, -h, Rm);
        const double c = -(test::evaluate(*block, test::frame(at_rest, Rp)).loads[3 + axis] -
                           test::evaluate(*block, test::frame(at_rest, Rm)).loads[3 + axis]) /
                         (2 * h);
        CHECK(c == doctest::Approx(expected).epsilon(1e-7));
    }
    CHECK(test::oc3_buoyancy_centre() == doctest::Approx(-62.07).epsilon(1e-3)); // the report's COB
}

TEST_CASE("in large rotations the buoyancy stays vertical and equal to rho g V_submerged") {
    const auto block = strip_theory_block(test::oc3_spar());
    const double u[3] = {1 / std::sqrt(2.0), 1 / std::sqrt(2.0), 0};
    for (double angle : {0.3, 0.5, 0.8}) {
        double R[9];
        test::rotation(u, angle, R);
        const double r[3] = {5.0, -3.0, -2.0};
        const auto e = test::evaluate(*block, test::frame(r, R));
        // The axis crosses the surface 2 / cos m above the origin, in the 6.5 m
        // column: the upright volume plus that length of the column.
        const double v = test::oc3_volume() + pi * 3.25 * 3.25 * 2 / std::cos(angle);
        CHECK(e.out[6] == doctest::Approx(v).epsilon(1e-12));
        CHECK(std::abs(e.out[0]) < 1e-6);
        CHECK(std::abs(e.out[1]) < 1e-6);
        CHECK(e.out[2] == doctest::Approx(rho * g * v).epsilon(1e-12));
        // Body axes: R^T of the ground force.
        for (int i = 0; i < 3; ++i)
            CHECK(e.loads[static_cast<std::size_t>(i)] ==
                  doctest::Approx(R[6 + i] * rho * g * v).epsilon(1e-12).scale(1));
        // The moment about the origin: that of rho g V at the centroid of the wet
        // volume, integrated slice by slice for the column (the rest is whole).
        double top[3], bottom[3];
        for (int i = 0; i < 3; ++i) {
            top[i] = r[i] + 10 * R[3 * i + 2];
            bottom[i] = r[i] - 4 * R[3 * i + 2];
        }
        const Slices column = slice_integral(bottom, top, 3.25, 3.25);
        CHECK(column.volume ==
              doctest::Approx(v - test::oc3_volume() + pi * 3.25 * 3.25 * 4).epsilon(1e-7));
        const double v_low = test::oc3_volume() - pi * 3.25 * 3.25 * 4;
        const double z_low =
            (test::oc3_volume() * test::oc3_buoyancy_centre() + pi * 3.25 * 3.25 * 4 * 2) /
            v_low; // centroid of the parts below -4 m, body axes
        double centroid_moment[3];
        for (int i = 0; i < 3; ++i)
            centroid_moment[i] = column.moment[i] + v_low * (r[i] + z_low * R[3 * i + 2]);
        // M = (c - r) x (0, 0, rho g V) = rho g (m - V r) x e_z
        const double mx = rho * g * (centroid_moment[1] - v * r[1]);
        const double my = -rho * g * (centroid_moment[0] - v * r[0]);
        CHECK(e.out[3] == doctest::Approx(mx).epsilon(1e-6));
        CHECK(e.out[4] == doctest::Approx(my).epsilon(1e-6));
        CHECK(std::abs(e.out[5]) < 1e-3);
    }
}

TEST_CASE("a tapered member cut obliquely by the still-water plane, either end down") {
    const double a[3] = {1, 2, -6}, b[3] = {3, -1, 5};
    for (bool flipped : {false, true}) {
        const StripSetup s = flipped ? one_member(b, a, 2.4, 4.0) : one_member(a, b, 4.0, 2.4);
        const auto block = strip_theory_block(s);
        const auto e = test::evaluate(*block, test::frame(at_rest, identity));
        const Slices wet = slice_integral(a, b, 2.0, 1.2);
        CHECK(e.out[6] == doctest::Approx(wet.volume).epsilon(1e-7));
        CHECK(e.out[2] == doctest::Approx(rho * g * wet.volume).epsilon(1e-7));
        CHECK(e.out[3] == doctest::Approx(rho * g * wet.moment[1]).epsilon(1e-6));
        CHECK(e.out[4] == doctest::Approx(-rho * g * wet.moment[0]).epsilon(1e-6));
    }
}

TEST_CASE("members modelled by potential flow carry no buoyancy") {
    StripSetup s = test::oc3_spar();
    for (StripMember& m : s.members) m.potential_flow = true;
    const auto e = test::evaluate(*strip_theory_block(s), test::frame(at_rest, identity));
    for (double l : e.loads) CHECK(l == 0);
    double A[36];
    strip_theory_block(s)->added_mass(0, nullptr, nullptr, A);
    for (double x : A) CHECK(x == 0);
}
