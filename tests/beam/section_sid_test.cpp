// The shape integrals of the part of a beam beyond a node (beam::make_section_sid):
// closed forms over [z_k, L] of a uniform beam, the root node's equal the whole
// beam's, the tip node's are empty; on ElastoDyn's element centres half the node's
// element counts, a quarter element out.
#include "beam/make_sid.hpp"
#include "beam_test_support.hpp"

#include <cmath>
#include <doctest/doctest.h>

using namespace yamsc;

namespace {

constexpr double L = 10, m = 3;

beam::Beam uniform(int elements = 0) {
    beam::Beam b = beam_test::uniform_beam(L, m, 7e4, 2e4, 0);
    b.modes = {beam_test::power_mode("a", 0, 2, 0.01), beam_test::power_mode("b", 1, 3)};
    b.integration_stations = 5; // nodes at z = 0, 2.5, 5, 7.5, 10
    b.elements = elements;
    return b;
}

doctest::Approx exact(double v) {
    return doctest::Approx(v).epsilon(1e-12);
}

} // namespace

TEST_CASE("section SID: the integrals over the part beyond a node") {
    const beam::Beam b = uniform();
    const double s = 5; // node 3 (index 2)
    const sid::Sid part = beam::make_section_sid(b, 2);
    CHECK(part.mass == exact(m * (L - s)));
    CHECK(part.md_cm.at0(2, 0) == exact(m * (L * L - s * s) / 2));
    // ∫_s^L (z/L)^2 m dz and ∫_s^L (z/L)^3 m dz
    CHECK(part.md_cm.at1(0, 0, 0) == exact(m * (L * L * L - s * s * s) / (3 * L * L)));
    CHECK(part.Ct.at0(1, 1) == exact(m * (std::pow(L, 4) - std::pow(s, 4)) / (4 * L * L * L)));
    CHECK(part.J.at0(0, 0) == exact(m * (L * L * L - s * s * s) / 3));
    CHECK(part.Me.at0(0, 0) == exact(m * (std::pow(L, 5) - std::pow(s, 5)) / (5 * std::pow(L, 4))));
    // The axial shortening of the part, -∫_s^L m ∫_0^z Φ_a'^2 = -(4/3) m (L^4 - s^4) / (4 L^4):
    // second order of md_z, Ct1 (K_gt) of the first mode along z.
    CHECK(part.Ct.at1(0, 2, 0) ==
          exact(-m * (std::pow(L, 4) - std::pow(s, 4)) / (3 * std::pow(L, 4))));
    CHECK(part.nodes.empty());
    CHECK(part.Ke.at0(0, 0) == 0);
}

TEST_CASE("section SID: the root node's is the whole beam's, the tip node's is empty") {
    const beam::Beam b = uniform();
    const sid::Sid whole = beam::make_sid(b), root = beam::make_section_sid(b, 0);
    CHECK(root.mass == whole.mass);
    CHECK(root.J.at1(0, 2, 0) == whole.J.at1(0, 2, 0));
    CHECK(root.Ct.at1(0, 2, 0) == whole.Ct.at1(0, 2, 0));
    CHECK(root.Gr.at0(1, 0) == whole.Gr.at0(1, 0));
    const sid::Sid tip = beam::make_section_sid(b, 4);
    CHECK(tip.mass == 0);
    CHECK(tip.J.at0(0, 0) == 0);
}

TEST_CASE("section SID: ElastoDyn's element centres keep half their element") {
    const beam::Beam b = uniform(4); // centres at 1.25, 3.75, 6.25, 8.75 (nodes 2 to 5)
    const double dr = L / 4;
    const sid::Sid part = beam::make_section_sid(b, 2); // the centre at 3.75
    CHECK(part.mass == exact(m * (2.5 * dr)));
    // the half element at 3.75 + dr/4, the two beyond at their centres
    CHECK(part.md_cm.at0(2, 0) == exact(m * dr * (0.5 * (3.75 + dr / 4) + 6.25 + 8.75)));
    CHECK_THROWS(beam::make_section_sid(b, 6)); // nodes 0 .. 5
}
