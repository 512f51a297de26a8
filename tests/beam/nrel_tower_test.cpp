// The NREL 5-MW onshore tower from its ElastoDyn file against the values of the paper
// (section 4.4) and OpenFAST (data/README.md).
#include "beam/elastodyn.hpp"
#include "beam/make_sid.hpp"
#include "beam_test_support.hpp"

#include <cmath>
#include <doctest/doctest.h>

using namespace yamsc;

namespace {

constexpr double kTowerLength = 87.6, kG = 9.807;

sid::Sid tower_sid(const std::vector<std::string>& modes) {
    diag::Diagnostics diags;
    auto beam = beam::read_elastodyn_tower(beam_test::nrel_file(beam_test::kTowerFile),
                                           kTowerLength, modes, diags);
    INFO(diags.render());
    REQUIRE(beam);
    REQUIRE(!diags.has_errors());
    REQUIRE(diags.all().empty()); // the shapes add up to 1: no warning
    return beam::make_sid(*beam);
}

doctest::Approx within(double v, double fraction) {
    return doctest::Approx(v).epsilon(fraction);
}

} // namespace

TEST_CASE("NREL 5-MW tower, fore-aft mode 1: paper section 4.4") {
    const sid::Sid s = tower_sid({"fa1"});
    MESSAGE("Me " << s.Me.at0(0, 0) << " Ke " << s.Ke.at0(0, 0) << " tip slope "
                  << s.nodes.back().psi.at0(1, 0) << " g Kgt " << kG * s.Ct.at1(0, 2, 0)
                  << " top mass " << 3.5e5 * kG * s.nodes.back().phi.at1(2, 0, 0));
    CHECK(s.mass == within(347460, 1e-3)); // the tower mass of the NREL report
    CHECK(s.Me.at0(0, 0) == within(5.40e4, 0.01));
    CHECK(s.Ke.at0(0, 0) == within(1.91e6, 0.01));
    CHECK(s.nodes.back().psi.at0(1, 0) == within(0.01852, 0.01)); // nu_y, about +y
    CHECK(s.nodes.back().phi.at0(0, 0) == within(1, 1e-12));
    // self weight: (a_z - g_z) K_gt,z with g_z = -g
    CHECK(kG * s.Ct.at1(0, 2, 0) == within(-1.04e4, 0.01));
    // rotor-nacelle mass at the top: its weight works on the top's axial shortening
    CHECK(3.5e5 * kG * s.nodes.back().phi.at1(2, 0, 0) == within(-5.2e4, 0.01));
    // 1 % damping: D = 2 zeta sqrt(K M)
    CHECK(s.De.at0(0, 0) == within(0.02 * std::sqrt(s.Ke.at0(0, 0) * s.Me.at0(0, 0)), 1e-12));
    CHECK(s.nodes.size() == 50);
}

TEST_CASE("NREL 5-MW tower, four modes: order, directions, symmetry") {
    const sid::Sid s = tower_sid({"ss1", "fa1", "fa2", "ss2"});
    CHECK(s.mode_names == std::vector<std::string>{"ss1", "fa1", "fa2", "ss2"});
    const sid::Node& top = s.nodes.back();
    CHECK(top.phi.at0(1, 0) == within(1, 1e-12)); // ss along y
    CHECK(top.phi.at0(0, 0) == 0);
    CHECK(top.phi.at0(0, 2) == within(1, 1e-12));
    CHECK(top.psi.at0(0, 0) < 0); // a y displacement turns the top about -x
    // fore-aft and side-side modes do not couple; same-direction modes do
    CHECK(s.Me.at0(0, 1) == 0);
    CHECK(s.Ke.at0(1, 2) != 0);
    for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) {
            CHECK(s.Me.at0(j, k) == s.Me.at0(k, j));
            CHECK(s.Ke.at0(j, k) == s.Ke.at0(k, j));
            CHECK(s.Ct.at1(j, 2, k) == s.Ct.at1(k, 2, j));
        }
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            CHECK(s.J.at0(r, c) == s.J.at0(c, r));
            for (int k = 0; k < 4; ++k) CHECK(s.J.at1(r, c, k) == s.J.at1(c, r, k));
        }
    // second modes are stiffer
    CHECK(s.Ke.at0(2, 2) / s.Me.at0(2, 2) > 10 * s.Ke.at0(1, 1) / s.Me.at0(1, 1));
}
