// The blade-element plan `yamsc fmu` writes into a unit's glue
// (yamsc/fmi/blade_elements.hpp): read back, every number is the same double.
#include <yamsc/fmi/blade_elements.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace {

using yamsc::fmi::BladeElementsPlan;

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_point(const yamsc::runtime::BodyPoint& a, const yamsc::runtime::BodyPoint& b) {
    auto vectors = [](const std::vector<Eigen::Vector3d>& x,
                      const std::vector<Eigen::Vector3d>& y) {
        if (x.size() != y.size()) return false;
        for (std::size_t k = 0; k < x.size(); ++k)
            for (int i = 0; i < 3; ++i)
                if (!same_bits(x[k][i], y[k][i])) return false;
        return true;
    };
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            if (!same_bits(a.orientation(r, c), b.orientation(r, c))) return false;
    return vectors({a.origin}, {b.origin}) && vectors(a.phi, b.phi) && vectors(a.psi, b.psi) &&
           vectors(a.phi1, b.phi1);
}

/// Numbers whose shortest text is long, tiny, huge, negative zero.
double awkward(int k) {
    const double values[] = {0.1,      1.0 / 3,
                             -2.0 / 3, std::nextafter(1.0, 2.0),
                             5e-324,   std::numeric_limits<double>::max(),
                             -0.0,     63.0 * 0.1,
                             1e23,     -1.2345678901234567e-8};
    return values[k % 10] * (1 + k / 10);
}

yamsc::runtime::BodyPoint point(int seed, int modes) {
    yamsc::runtime::BodyPoint p;
    int k = seed;
    for (int i = 0; i < 3; ++i) p.origin[i] = awkward(k++);
    for (int m = 0; m < modes; ++m) {
        p.phi.emplace_back(awkward(k), awkward(k + 1), awkward(k + 2));
        p.psi.emplace_back(awkward(k + 3), awkward(k + 4), awkward(k + 5));
        k += 6;
    }
    for (int m = 0; m < modes * modes; ++m, k += 3)
        p.phi1.emplace_back(awkward(k), awkward(k + 1), awkward(k + 2));
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) p.orientation(r, c) = awkward(k++);
    return p;
}

BladeElementsPlan plan() {
    BladeElementsPlan p;
    p.aerodyn = "aerodyn/deck with spaces/AeroDyn15 \"v\".dat\n";
    p.inflow_angle_tolerance = awkward(1);
    p.setup.output_prefix = "aero_";
    p.setup.frozen_wake = true;
    p.setup.difference_step = awkward(3);
    p.setup.channels.wind = 4;
    p.setup.channels.pitch = -1;
    p.setup.channels.hub_outputs = {7, 8, 9, 10};
    for (int b = 0; b < 3; ++b) {
        yamsc::aero::BladeElementChannels::Blade blade;
        blade.outputs = {20 + b, 30 + b};
        blade.loads = {1, 2, 3};
        for (int n = 0; n < 4; ++n) blade.points.push_back(point(17 * b + n, 2));
        p.setup.channels.blades.push_back(blade);
    }
    p.setup.channels.tower.outputs = {40};
    p.setup.channels.tower.points.push_back(point(5, 0));
    return p;
}

} // namespace

TEST_CASE("a blade-element plan's text reads back with every number exact") {
    const BladeElementsPlan a = plan();
    const std::string text = yamsc::fmi::blade_elements_plan_text(a);
    const BladeElementsPlan b = yamsc::fmi::read_blade_elements_plan(text);
    CHECK(b.aerodyn == a.aerodyn);
    CHECK(same_bits(b.inflow_angle_tolerance, a.inflow_angle_tolerance));
    CHECK(b.setup.output_prefix == a.setup.output_prefix);
    CHECK(b.setup.frozen_wake);
    CHECK(same_bits(b.setup.difference_step, a.setup.difference_step));
    CHECK(b.setup.channels.wind == 4);
    CHECK(b.setup.channels.pitch == -1);
    CHECK(b.setup.channels.hub_outputs == a.setup.channels.hub_outputs);
    REQUIRE(b.setup.channels.blades.size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
        const auto& x = a.setup.channels.blades[k];
        const auto& y = b.setup.channels.blades[k];
        CHECK(y.outputs == x.outputs);
        CHECK(y.loads == x.loads);
        REQUIRE(y.points.size() == x.points.size());
        for (std::size_t n = 0; n < x.points.size(); ++n)
            CHECK(same_point(y.points[n], x.points[n]));
    }
    CHECK(b.setup.channels.tower.outputs == a.setup.channels.tower.outputs);
    CHECK(b.setup.channels.tower.loads.empty());
    REQUIRE(b.setup.channels.tower.points.size() == 1);
    CHECK(same_point(b.setup.channels.tower.points[0], a.setup.channels.tower.points[0]));
    CHECK(std::signbit(b.setup.channels.blades[0].points[0].phi1.at(1)[0]) ==
          std::signbit(a.setup.channels.blades[0].points[0].phi1.at(1)[0]));
    // Written again: the same text.
    CHECK(yamsc::fmi::blade_elements_plan_text(b) == text);
}

TEST_CASE("a damaged plan is refused, naming the byte") {
    const std::string text = yamsc::fmi::blade_elements_plan_text(plan());
    CHECK_THROWS_AS(yamsc::fmi::read_blade_elements_plan(text.substr(0, text.size() / 2)),
                    std::invalid_argument);
    CHECK_THROWS_AS(yamsc::fmi::read_blade_elements_plan(text + " 1"), std::invalid_argument);
    std::string bad = text;
    bad.replace(bad.find("difference_step ") + 16, 1, "x");
    CHECK_THROWS_WITH_AS(yamsc::fmi::read_blade_elements_plan(bad), doctest::Contains("byte"),
                         std::invalid_argument);
    CHECK_THROWS_AS(yamsc::fmi::read_blade_elements_plan(""), std::invalid_argument);
}
