// The elastic catenary with seabed contact: its closed form against the line's
// equilibrium integrated along its length, the solver as the closed form's
// inverse in each regime, exact derivatives against central differences.
#include <yamsc/mooring/catenary.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

using namespace yamsc::runtime::mooring;

namespace {

// The fairlead's span found by integrating the stretched line from the anchor:
// along the seabed the tension falls by friction towards the anchor and is
// never negative; in the water it is (H, V - w (L - s)) and each element
// stretches by T / EA. Composite Simpson, enough panels for 1e-11.
Span integrated_span(const LineProperties& line, double h, double v) {
    const double w = line.weight_in_fluid, L = line.length, EA = line.axial_stiffness;
    const bool on_seabed = line.seabed_friction >= 0 && v < w * L;
    const double lb = on_seabed ? L - v / w : 0; // unstretched length on the seabed
    auto simpson = [](auto f, double a, double b) {
        const int n = 20000;
        const double step = (b - a) / n;
        double sum = f(a) + f(b);
        for (int i = 1; i < n; ++i) sum += f(a + i * step) * (i % 2 ? 4 : 2);
        return sum * step / 3;
    };
    Span s;
    if (lb > 0) {
        const double cb = line.seabed_friction;
        s.horizontal +=
            simpson([&](double x) { return 1 + std::max(h - cb * w * (lb - x), 0.0) / EA; }, 0, lb);
    }
    auto tension = [&](double x) { return std::hypot(h, v - w * (L - x)); };
    s.horizontal +=
        simpson([&](double x) { return h / tension(x) * (1 + tension(x) / EA); }, lb, L);
    s.vertical += simpson(
        [&](double x) { return (v - w * (L - x)) / tension(x) * (1 + tension(x) / EA); }, lb, L);
    return s;
}

const LineProperties oc3_line{902.2, 384243000.0, 698.094, 0.0};

} // namespace

TEST_CASE("the closed form equals the line integrated along its length, in every regime") {
    struct Case {
        const char* regime;
        LineProperties line;
        double h, v;
    };
    const Case cases[] = {
        {"hanging, no seabed", {902.2, 384243000.0, 698.094, -1.0}, 7.8e5, 5.6e5},
        {"lifted off a seabed", {500.0, 2.0e8, 698.094, 1.0}, 4.0e5, 4.0e5},
        {"on the seabed, anchor loaded", oc3_line, 7.4e5, 5.4e5},
        {"on the seabed, anchor slack by friction",
         {902.2, 384243000.0, 698.094, 1.0},
         5.0e4,
         2.0e5},
        {"taut and stretchy", {300.0, 1.0e6, 100.0, -1.0}, 2.0e5, 1.5e5},
    };
    for (const Case& c : cases) {
        CAPTURE(c.regime);
        const Span closed = catenary_span(c.line, c.h, c.v);
        const Span integrated = integrated_span(c.line, c.h, c.v);
        CHECK(closed.horizontal == doctest::Approx(integrated.horizontal).epsilon(1e-11));
        CHECK(closed.vertical == doctest::Approx(integrated.vertical).epsilon(1e-11));
    }
}

TEST_CASE("the solver inverts the closed form; its stiffness is the inverse of the span's "
          "derivatives, which equal central differences") {
    struct Case {
        LineProperties line;
        double h, v;
    };
    const Case cases[] = {{{902.2, 384243000.0, 698.094, -1.0}, 7.8e5, 5.6e5},
                          {{500.0, 2.0e8, 698.094, 1.0}, 4.0e5, 4.0e5},
                          {oc3_line, 7.4e5, 5.4e5},
                          {{902.2, 384243000.0, 698.094, 1.0}, 5.0e4, 2.0e5}};
    for (const Case& c : cases) {
        double d[4];
        const Span span = catenary_span(c.line, c.h, c.v, d);
        const CatenarySolution s = solve_catenary(c.line, span);
        CHECK(s.fairlead_horizontal == doctest::Approx(c.h).epsilon(1e-10));
        CHECK(s.fairlead_vertical == doctest::Approx(c.v).epsilon(1e-10));
        CHECK(s.iterations < 30);
        // d(x, z)/d(H, V) against central differences (relative steps 1e-6).
        const double eh = 1e-6 * c.h, ev = 1e-6 * c.v;
        const Span hp = catenary_span(c.line, c.h + eh, c.v),
                   hm = catenary_span(c.line, c.h - eh, c.v);
        const Span vp = catenary_span(c.line, c.h, c.v + ev),
                   vm = catenary_span(c.line, c.h, c.v - ev);
        const double fd[4] = {
            (hp.horizontal - hm.horizontal) / (2 * eh), (vp.horizontal - vm.horizontal) / (2 * ev),
            (hp.vertical - hm.vertical) / (2 * eh), (vp.vertical - vm.vertical) / (2 * ev)};
        for (int i = 0; i < 4; ++i) CHECK(d[i] == doctest::Approx(fd[i]).epsilon(1e-6).scale(1e-9));
        // The stiffness times the compliance is the identity.
        const double* k = s.stiffness;
        CHECK(k[0] * d[0] + k[1] * d[2] == doctest::Approx(1).epsilon(1e-9));
        CHECK(k[0] * d[1] + k[1] * d[3] == doctest::Approx(0).scale(1e-9));
        CHECK(k[2] * d[0] + k[3] * d[2] == doctest::Approx(0).scale(1e-9));
        CHECK(k[2] * d[1] + k[3] * d[3] == doctest::Approx(1).epsilon(1e-9));
    }
}

TEST_CASE("the ends' tensions: the anchor takes what friction leaves, and the line's weight") {
    const double span_x = 848.67, span_z = 250; // the OC3 line at rest
    const CatenarySolution s = solve_catenary(oc3_line, {span_x, span_z});
    CHECK(s.length_on_seabed > 0);
    // Without friction the horizontal tension is the same along the line, and the
    // suspended length's weight is the fairlead's vertical tension.
    CHECK(s.anchor_horizontal == doctest::Approx(s.fairlead_horizontal).epsilon(1e-15));
    CHECK(s.anchor_vertical == 0);
    CHECK(s.fairlead_vertical ==
          doctest::Approx(oc3_line.weight_in_fluid * (oc3_line.length - s.length_on_seabed))
              .epsilon(1e-12));
    LineProperties rough = oc3_line;
    rough.seabed_friction = 1.0;
    const CatenarySolution r = solve_catenary(rough, {span_x, span_z});
    CHECK(r.anchor_horizontal ==
          doctest::Approx(r.fairlead_horizontal -
                          rough.weight_in_fluid * r.length_on_seabed * rough.seabed_friction)
              .epsilon(1e-12));
}

TEST_CASE("a line that cannot reach, or is too long for its span, is refused with the reason") {
    CHECK_THROWS_WITH_AS(solve_catenary(oc3_line, {100, 250}),
                         doctest::Contains("longer than the span allows"), std::runtime_error);
    CHECK_THROWS_WITH_AS(solve_catenary(oc3_line, {848.67, -10}),
                         doctest::Contains("above its anchor"), std::runtime_error);
    LineProperties massless = oc3_line;
    massless.weight_in_fluid = 0;
    CHECK_THROWS_WITH_AS(solve_catenary(massless, {848.67, 250}),
                         doctest::Contains("weight in fluid"), std::runtime_error);
}
