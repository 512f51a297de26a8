// Closed forms of the shape integrals of a uniform beam (paper Appendix A-C) with
// Phi_a = (z/L)^2 e_x and Phi_b = (z/L)^3 e_y.
#include "beam/make_sid.hpp"
#include "beam_test_support.hpp"
#include "diag/diagnostics.hpp"

#include <cmath>
#include <doctest/doctest.h>

using namespace yamsc;

namespace {

constexpr double L = 10, m = 3, EIy = 7e4, EIx = 2e4;

/// The integrals of polynomials are exact up to rounding.
doctest::Approx exact(double v) {
    return doctest::Approx(v).epsilon(1e-11);
}

sid::Sid uniform_sid(double twist = 0) {
    beam::Beam b = beam_test::uniform_beam(L, m, EIy, EIx, twist);
    b.modes = {beam_test::power_mode("a", 0, 2, 0.01), beam_test::power_mode("b", 1, 3)};
    return beam::make_sid(b);
}

} // namespace

TEST_CASE("uniform beam: rigid-body integrals") {
    const sid::Sid s = uniform_sid();
    CHECK(s.nq == 2);
    CHECK(s.mode_names == std::vector<std::string>{"a", "b"});
    CHECK(s.mass == exact(m * L));
    CHECK(s.md_cm.at0(2, 0) == exact(m * L * L / 2));
    CHECK(s.md_cm.at1(0, 0, 0) == exact(m * L / 3)); // integral of Phi_a dm
    CHECK(s.md_cm.at1(1, 0, 1) == exact(m * L / 4));
    CHECK(s.J.at0(0, 0) == exact(m * L * L * L / 3));
    CHECK(s.J.at0(1, 1) == exact(m * L * L * L / 3));
    CHECK(s.J.at0(2, 2) == doctest::Approx(0).epsilon(1e-12));
    // -(skew(s0) skew(Phi) + skew(Phi) skew(s0)): -z phi in the xz entries
    CHECK(s.J.at1(0, 2, 0) == exact(-m * L * L / 4));
    CHECK(s.J.at1(2, 0, 0) == exact(-m * L * L / 4));
    CHECK(s.J.at1(1, 2, 1) == exact(-m * L * L / 5));
}

TEST_CASE("uniform beam: elastic mass, stiffness and damping (B1, B2)") {
    const sid::Sid s = uniform_sid();
    CHECK(s.Me.at0(0, 0) == exact(m * L / 5));
    CHECK(s.Me.at0(1, 1) == exact(m * L / 7));
    CHECK(s.Me.at0(0, 1) == doctest::Approx(0).epsilon(1e-12));
    CHECK(s.Ke.at0(0, 0) == exact(4 * EIy / (L * L * L)));  // phi'' = 2/L^2
    CHECK(s.Ke.at0(1, 1) == exact(12 * EIx / (L * L * L))); // phi'' = 6z/L^3
    CHECK(s.Ke.at0(0, 1) == doctest::Approx(0).epsilon(1e-12));
    CHECK(s.De.at0(0, 0) == exact(2 * 0.01 * std::sqrt(s.Ke.at0(0, 0) * s.Me.at0(0, 0))));
    CHECK(s.De.at0(1, 1) == 0);
    CHECK(s.Ct.at0(0, 0) == exact(m * L / 3));
    CHECK(s.Ct.at0(1, 1) == exact(m * L / 4));
    CHECK(s.Cr.at0(0, 1) == exact(m * L * L / 4));  // s0 x Phi_a = z phi e_y
    CHECK(s.Cr.at0(1, 0) == exact(-m * L * L / 5)); // s0 x Phi_b = -z phi e_x
    CHECK(s.Cr.at1(1, 2, 0) == exact(m * L / 6));   // Phi_a x Phi_b = e_z
    CHECK(s.Cr.at1(0, 2, 1) == exact(-m * L / 6));
}

TEST_CASE("uniform beam: gyroscopic and centrifugal terms (A11-A14)") {
    const sid::Sid s = uniform_sid();
    CHECK(s.Gr.at0(0, 2) == exact(-m * L * L / 2)); // -2 int phi z e_x e_z^T
    CHECK(s.Gr.at0(1, 3 + 2) == exact(-2 * m * L * L / 5));
    CHECK(s.Ge.at0(0, 3 * 1 + 2) == exact(-m * L / 3)); // -2 Phi_a^T skew(Phi_b)
    CHECK(s.Ge.at0(1, 3 * 0 + 2) == exact(m * L / 3));
    CHECK(s.Oe.at0(0, 5) == exact(m * L * L / 4)); // O13 + O31
    CHECK(s.Oe.at0(1, 4) == exact(m * L * L / 5)); // O23 + O32
    // O_e = -Gr^T / 2 (eq. A12)
    CHECK(s.Oe.at0(0, 5) == exact(-s.Gr.at0(0, 2) / 2));
}

TEST_CASE("uniform beam: geometric stiffness in the first-order terms (C3, C5)") {
    const sid::Sid s = uniform_sid();
    // K_gt,z = -int m (L - z) phi'^2 = -m/3; a transverse acceleration stiffens nothing
    CHECK(s.Ct.at1(0, 2, 0) == exact(-m / 3));
    CHECK(s.Ct.at1(0, 0, 0) == 0);
    CHECK(s.Ct.at1(0, 2, 1) == doctest::Approx(0).epsilon(1e-12));
    CHECK(s.Ct.at1(1, 2, 1) == exact(-0.3 * m)); // -9m/L^6 int (L-z) z^4
    // K_gw,xx = int m (L^2 - z^2)/2 phi'^2 = 4mL/15, on top of int skew(Phi)skew(Phi) dm
    CHECK(s.Oe.at1(0, 0, 0) == exact(4 * m * L / 15));
    CHECK(s.Oe.at1(0, 1, 0) == exact(-m * L / 5 + 4 * m * L / 15));
    CHECK(s.Oe.at1(0, 2, 0) == exact(-m * L / 5));
    CHECK(s.Oe.at1(0, 3, 0) == doctest::Approx(0).epsilon(1e-12));
    // rotation about z loads nothing axially
    CHECK(s.Cr.at1(0, 0, 0) == doctest::Approx(0).epsilon(1e-12));
}

TEST_CASE("uniform beam: nodes") {
    const sid::Sid s = uniform_sid();
    REQUIRE(s.nodes.size() == 11);
    const sid::Node& tip = s.nodes.back();
    CHECK(tip.id == 11);
    CHECK(tip.rframe == "body ref");
    CHECK(tip.origin.at0(2, 0) == exact(L));
    CHECK(tip.origin.at1(0, 0, 0) == exact(1));
    CHECK(tip.phi.at0(0, 0) == exact(1));
    CHECK(tip.phi.at0(1, 1) == exact(1));
    CHECK(tip.psi.at0(1, 0) == exact(2 / L));  // x displacement turns about +y
    CHECK(tip.psi.at0(0, 1) == exact(-3 / L)); // y displacement turns about -x
    CHECK(tip.ap.at0(1, 1) == 1);
    CHECK(tip.ap.at1(0, 2, 0) == exact(2 / L)); // skew(psi)
    CHECK(tip.phi.at1(2, 0, 0) == exact(-4 / (3 * L)));
    CHECK(tip.phi.at1(2, 1, 1) == exact(-9 / (5 * L)));
    const sid::Node& mid = s.nodes[5];
    CHECK(mid.origin.at0(2, 0) == exact(L / 2));
    CHECK(mid.phi.at0(0, 0) == exact(0.25));
    CHECK(mid.phi.at1(2, 0, 0) == exact(-4.0 / (3 * L) / 8)); // -4 z^3 / (3 L^4)
    CHECK(s.nodes.front().phi.at0(0, 0) == exact(0).epsilon(1e-14));
}

TEST_CASE("constant twist turns the shapes, not the modal stiffness") {
    const double t = 0.3;
    const sid::Sid s = uniform_sid(t);
    const sid::Node& tip = s.nodes.back();
    CHECK(tip.phi.at0(0, 0) == exact(std::cos(t)));
    CHECK(tip.phi.at0(1, 0) == exact(std::sin(t)));
    CHECK(tip.phi.at0(0, 1) == exact(-std::sin(t)));
    CHECK(s.Ke.at0(0, 0) == exact(4 * EIy / (L * L * L)));
    CHECK(s.Ke.at0(1, 1) == exact(12 * EIx / (L * L * L)));
    CHECK(s.Me.at0(0, 0) == exact(m * L / 5));
}

TEST_CASE("linear mass and a station inside the span are integrated exactly") {
    beam::Beam b = beam_test::uniform_beam(L, m, EIy, EIx);
    b.stations = {{0, 2 * m, EIx, EIy, 0}, {0.37, m, EIx, EIy, 0}, {1, m, EIx, EIy, 0}};
    b.modes = {beam_test::power_mode("a", 0, 2)};
    const sid::Sid s = beam::make_sid(b);
    // mass: trapezoid over [0, 0.37] plus m over the rest
    CHECK(s.mass == exact(m * L * (1 + 0.37 / 2)));
    // Me = m L [int_0^1 x^4 + int_0^0.37 (1 - x/0.37) x^4]
    const double a = 0.37, extra = std::pow(a, 5) / 5 - std::pow(a, 5) / 6;
    CHECK(s.Me.at0(0, 0) == exact(m * L * (0.2 + extra)));
}

TEST_CASE("a beam without modes is a rigid body with nodes") {
    beam::Beam b = beam_test::uniform_beam(L, m, EIy, EIx);
    const sid::Sid s = beam::make_sid(b);
    CHECK(s.nq == 0);
    CHECK(s.mass == exact(m * L));
    CHECK(s.Me.m0.empty());
    CHECK(s.nodes.size() == 11);
    CHECK(s.nodes.back().phi.ncol == 0);
}

TEST_CASE("check_beam names the first problem; make_sid refuses a bad beam") {
    beam::Beam b = beam_test::uniform_beam(L, m, EIy, EIx);
    CHECK(!beam::check_beam(b));
    b.stations[1].s = 0;
    CHECK(beam::check_beam(b).value_or("").find("increasing") != std::string::npos);
    CHECK_THROWS_AS(beam::make_sid(b), diag::InternalError);
    b = beam_test::uniform_beam(L, m, EIy, EIx);
    b.integration_stations = 1;
    CHECK(beam::check_beam(b).value_or("").find("stations") != std::string::npos);
    b = beam_test::uniform_beam(-1, m, EIy, EIx);
    CHECK(beam::check_beam(b).value_or("").find("length") != std::string::npos);
    b = beam_test::uniform_beam(L, m, EIy, EIx);
    b.modes = {beam_test::power_mode("a", 2, 2)};
    CHECK(beam::check_beam(b).value_or("").find("direction") != std::string::npos);
}
