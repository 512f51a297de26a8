// The NREL 5-MW blade from its ElastoDyn file against the paper (section 4.3):
// frequencies at rest and Southwell coefficients of the rotating blade.
#include "beam/elastodyn.hpp"
#include "beam/make_sid.hpp"
#include "beam_test_support.hpp"

#include <cmath>
#include <doctest/doctest.h>

using namespace yamsc;

namespace {

constexpr double kBladeLength = 61.5, kPi = 3.14159265358979323846;

sid::Sid blade_sid() {
    diag::Diagnostics diags;
    auto beam = beam::read_elastodyn_blade(beam_test::nrel_file(beam_test::kBladeFile),
                                           kBladeLength, {"flap1", "edge1", "flap2"}, diags);
    INFO(diags.render());
    REQUIRE(beam);
    REQUIRE(diags.all().empty());
    return beam::make_sid(*beam);
}

doctest::Approx within(double v, double fraction) {
    return doctest::Approx(v).epsilon(fraction);
}

/// k_Omega = K_g(Omega) / (Me Omega^2) for a rotation about x with the root at r_h from
/// the axis: the origin's centripetal acceleration -Omega^2 r_h e_z enters through
/// (a_z - g_z) K_gt,z = Ct1, the spin through Omega^2 K_gw,xx. Oe1 holds K_gw plus
/// the inertial integral of skew(Phi) skew(Phi) (a a^T - |a|^2 I): for shapes in the
/// xy plane K_gw,xx = K_gw,yy = (Oe1_xx + Oe1_yy - Oe1_zz) / 2.
double southwell(const sid::Sid& s, int j, double r_h) {
    const double k_gw = (s.Oe.at1(j, 0, j) + s.Oe.at1(j, 1, j) - s.Oe.at1(j, 2, j)) / 2;
    return (k_gw - r_h * s.Ct.at1(j, 2, j)) / s.Me.at0(j, j);
}

} // namespace

TEST_CASE("NREL 5-MW blade: frequencies at rest") {
    const sid::Sid s = blade_sid();
    const double expected[3] = {0.68, 1.07, 1.94};
    for (int j = 0; j < 3; ++j) {
        const double f = std::sqrt(s.Ke.at0(j, j) / s.Me.at0(j, j)) / (2 * kPi);
        MESSAGE(s.mode_names[static_cast<std::size_t>(j)] << ": Me " << s.Me.at0(j, j) << " Ke "
                                                          << s.Ke.at0(j, j) << " f " << f);
        CHECK(f == within(expected[j], 0.05));
    }
    // the integral of the piecewise-linear table times AdjBlMs (ElastoDyn's coarser
    // element sums give the 17740 kg of the NREL report)
    CHECK(s.mass == within(17608.83, 1e-6));
    // twist couples flap and edge through the mass (not the stiffness, as in ElastoDyn)
    CHECK(s.Me.at0(0, 1) != 0);
    CHECK(std::fabs(s.Ke.at0(0, 1)) < 1e-12 * s.Ke.at0(0, 0));
    CHECK(s.Ke.at0(0, 2) != 0);                                  // flap 1 and flap 2 share FlpStff
    CHECK(s.nodes.back().phi.at0(1, 0) == within(-0.126, 0.01)); // flap tip leans to -y
}

TEST_CASE("NREL 5-MW blade: Southwell coefficients") {
    const sid::Sid s = blade_sid();
    const double paper[3] = {1.7, 1.4, 5.5};
    for (int j = 0; j < 3; ++j) {
        const double k_hub = southwell(s, j, 1.5), k_root = southwell(s, j, 0);
        MESSAGE(s.mode_names[static_cast<std::size_t>(j)]
                << ": k_Omega " << k_hub << " (root on the axis: " << k_root << ")");
        CHECK(k_hub == within(paper[j], 0.05));
        CHECK(k_root == within(paper[j], 0.02));
        CHECK(k_hub > k_root); // the hub radius adds centrifugal tension
    }
    // Edgewise, the blade swings in the plane of rotation (yz): the centrifugal force
    // pulls it back almost as much as it stiffens it: omega^2 (k_Omega - 1) (eq. 32;
    // "almost" because the twisted edge shape also moves along x, out of that plane).
    const double edge = (s.Oe.at1(1, 0, 1) - 1.5 * s.Ct.at1(1, 2, 1)) / s.Me.at0(1, 1);
    CHECK(edge > southwell(s, 1, 1.5) - 1);
    CHECK(edge < southwell(s, 1, 1.5) - 0.9);
}

TEST_CASE("NREL 5-MW blade (twisted shapes): identities between shape integrals") {
    const sid::Sid s = blade_sid();
    for (int j = 0; j < 3; ++j) {
        // O_e,j = -Gr_j^T / 2 (eq. A12), in the layout of eq. A14
        const int cols[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
        for (int c = 0; c < 6; ++c) {
            const int a = cols[c][0], b = cols[c][1];
            double expected = -s.Gr.at0(b, 3 * j + a) / 2;
            if (a != b) expected += -s.Gr.at0(a, 3 * j + b) / 2;
            CHECK(s.Oe.at0(j, c) == doctest::Approx(expected).epsilon(1e-12).scale(1e3));
        }
        // Ge(k, block j) = -2 int Phi_k^T skew(Phi_j) = -2 int Phi_k x Phi_j = -2 Cr1(j,:,k)
        // (a straight beam has no K_gr)
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a)
                CHECK(s.Ge.at0(k, 3 * j + a) ==
                      doctest::Approx(-2 * s.Cr.at1(j, a, k)).epsilon(1e-12).scale(1));
        // J and Me are symmetric
        for (int k = 0; k < 3; ++k) CHECK(s.Me.at0(j, k) == s.Me.at0(k, j));
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) CHECK(s.J.at1(r, c, j) == s.J.at1(c, r, j));
    }
}

TEST_CASE("NREL 5-MW blade: the integrals do not depend on the number of nodes") {
    diag::Diagnostics diags;
    auto beam = beam::read_elastodyn_blade(beam_test::nrel_file(beam_test::kBladeFile),
                                           kBladeLength, {"flap1", "edge1", "flap2"}, diags);
    REQUIRE(beam);
    beam->integration_stations = 3;
    const sid::Sid coarse = beam::make_sid(*beam);
    beam->integration_stations = 301;
    const sid::Sid fine = beam::make_sid(*beam);
    CHECK(coarse.nodes.size() == 3);
    CHECK(fine.nodes.size() == 301);
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) {
            const double scale = std::sqrt(fine.Me.at0(j, j) * fine.Me.at0(k, k));
            CHECK(coarse.Me.at0(j, k) ==
                  doctest::Approx(fine.Me.at0(j, k)).epsilon(1e-9).scale(scale));
            CHECK(coarse.Ke.at0(j, k) == doctest::Approx(fine.Ke.at0(j, k)).epsilon(1e-9));
            CHECK(coarse.Ct.at1(j, 2, k) == doctest::Approx(fine.Ct.at1(j, 2, k)).epsilon(1e-8));
        }
    // the tip node is the same point
    CHECK(coarse.nodes.back().phi.at0(0, 0) ==
          doctest::Approx(fine.nodes.back().phi.at0(0, 0)).epsilon(1e-10));
    CHECK(coarse.nodes.back().phi.at1(2, 0, 0) ==
          doctest::Approx(fine.nodes.back().phi.at1(2, 0, 0)).epsilon(1e-10));
}

TEST_CASE("NREL 5-MW blade on ElastoDyn's 17 elements (elements = BldNodes)") {
    diag::Diagnostics diags;
    auto beam = beam::read_elastodyn_blade(beam_test::nrel_file(beam_test::kBladeFile),
                                           kBladeLength, {"flap1", "edge1", "flap2"}, diags);
    REQUIRE(beam);
    beam->elements = 17;
    const sid::Sid s = beam::make_sid(*beam);
    // Root, 17 element centres, tip.
    REQUIRE(s.nodes.size() == 19);
    CHECK(s.nodes[1].origin.at0(2, 0) == doctest::Approx(kBladeLength / 34));
    // ElastoDyn's InitBlDefl with these tip shapes gives OpenFAST's initial DOFs for
    // OoPDefl = 2 m (tests/data/reference/land_16dof_free_decay, first row).
    const sid::Node& tip = s.nodes.back();
    const double fx = tip.phi.at0(0, 0), fy = tip.phi.at0(1, 0);
    const double ex = tip.phi.at0(0, 1), ey = tip.phi.at0(1, 1);
    const double det = fx * ey - ex * fy;
    CHECK(2 * ey / det == doctest::Approx(1.9752467222).epsilon(1e-9));
    CHECK(-2 * fy / det == doctest::Approx(0.25352369297).epsilon(1e-9));
    // ElastoDyn's damping: D(j,k) = 2 zeta_k K(j,k) / omega_k couples the flap modes
    // (indices: flap1 0, edge1 1, flap2 2) and is not symmetric.
    CHECK(s.De.at0(0, 2) != 0);
    CHECK(s.De.at0(0, 2) != doctest::Approx(s.De.at0(2, 0)));
    CHECK(std::fabs(s.De.at0(0, 1)) < 1e-12 * s.De.at0(0, 0)); // flap and edge: no Ke coupling
}
