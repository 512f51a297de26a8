// A HydroDyn input's strip-theory members as the block's setup: joints to ends,
// property sets to diameters, coefficient tables to each end, the joints' axial
// coefficients; errors at the member's line, warnings for what is not modelled.
#include "analysis/hydro_strip_setup.hpp"

#include <doctest/doctest.h>

using namespace yamsc;

namespace {

hydrodyn::Input oc3_input() {
    hydrodyn::Input in;
    in.axial = {{1, 0.0, 0.0, 1.0, 0, -1.0, 1.0, 20}};
    in.joints = {{1, {0, 0, -120}, 1, 0, 30},
                 {2, {0, 0, -12}, 1, 0, 31},
                 {3, {0, 0, -4}, 1, 0, 32},
                 {4, {0, 0, 10}, 1, 0, 33}};
    in.sections = {{1, 9.4, 1e-4, 40}, {2, 6.5, 1e-4, 41}};
    in.simple = {0.6, 0, 0.969954, 0, 1, 1, 0, 0, 1, 1, 1, 1};
    const int rows[3][6] = {{1, 1, 2, 1, 1, 60}, {2, 2, 3, 1, 2, 61}, {3, 3, 4, 2, 2, 62}};
    for (const auto& r : rows) {
        hydrodyn::Member m;
        m.id = r[0];
        m.joint1 = r[1];
        m.joint2 = r[2];
        m.section1 = r[3];
        m.section2 = r[4];
        m.division_size = 0.5;
        m.potential_flow = r[0] == 3;
        m.line = r[5];
        in.members.push_back(m);
    }
    return in;
}

} // namespace

TEST_CASE("the OC3 spar's members from its HydroDyn tables") {
    diag::Diagnostics d;
    runtime::hydro::Water w;
    const auto s = analysis::strip_setup(oc3_input(), w, d);
    REQUIRE(s);
    CHECK(!d.has_errors());
    REQUIRE(s->members.size() == 3);
    const auto& m = s->members[1];
    CHECK(m.end1[2] == -12);
    CHECK(m.end2[2] == -4);
    CHECK(m.diameter1 == 9.4);
    CHECK(m.diameter2 == 6.5);
    CHECK(m.c1.cd == 0.6);
    CHECK(m.c2.ca == 0.969954);
    CHECK(m.c1.ax_ca == 1);
    CHECK(m.joint1_axial.ax_cp == 1);
    CHECK(m.joint1_axial.ax_ca == 0);
    CHECK(!m.potential_flow);
    CHECK(s->members[2].potential_flow);
    CHECK(!s->kinematics_displaced);
}

TEST_CASE("member-based and depth-based coefficients at the member's ends") {
    auto in = oc3_input();
    in.members[0].coefficient_model = 3;
    hydrodyn::Coefficients a{}, b{};
    a.cd = 0.5;
    b.cd = 0.9;
    in.member_coefficients = {{1, a, b, 70}};
    in.members[1].coefficient_model = 2;
    hydrodyn::Coefficients shallow{}, deep{};
    shallow.ca = 1.0;
    deep.ca = 0.5;
    in.depth = {{0, shallow, 50}, {20, deep, 51}};
    diag::Diagnostics d;
    const auto s = analysis::strip_setup(in, runtime::hydro::Water{}, d);
    REQUIRE(s);
    CHECK(s->members[0].c1.cd == 0.5);
    CHECK(s->members[0].c2.cd == 0.9);
    CHECK(s->members[1].c1.ca == doctest::Approx(0.7)); // 12 m deep
    CHECK(s->members[1].c2.ca == doctest::Approx(0.9)); // 4 m deep
}

TEST_CASE("an unknown joint is an error at the member's line; AMMod 2 warns") {
    auto in = oc3_input();
    in.members[2].joint2 = 9;
    in.am_mod = 2;
    diag::Diagnostics d;
    CHECK(!analysis::strip_setup(in, runtime::hydro::Water{}, d));
    CHECK(d.has_errors());
    bool at_line = false, warned = false;
    for (const auto& m : d.all()) {
        if (m.loc.line == 62 && m.message.find("no joint with ID 9") != std::string::npos)
            at_line = true;
        if (m.message.find("AMMod 2") != std::string::npos) warned = true;
    }
    INFO(d.render());
    CHECK(at_line);
    CHECK(warned);
}
