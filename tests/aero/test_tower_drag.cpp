// The tower's own drag (AeroDyn's TwrAero) against its closed form and
// against what OpenFAST's tower base sees when it is switched on (twr_U8 vs
// flex_U8, the same flexible turbine with and without tower aerodynamics).
#include <cmath>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "tower_reference.hpp"
#include "yamsc/aero/tower_influence.hpp"

using namespace yamsc::aero;

TEST_CASE("tower drag per length is 1/2 rho Cd D |V_n| V_n of the wind relative to the node") {
    const TowerNode node{40, 5, 0.9, 0.1};
    const double rho = 1.225;
    const Vec3 z{0, 0, 1};
    Vec3 f = tower_drag_per_length(node, rho, {8, 0, 0}, {0, 0, 0}, z);
    CHECK(f[0] == doctest::Approx(0.5 * rho * 0.9 * 5 * 64));
    CHECK(f[1] == 0);
    CHECK(f[2] == 0);
    // the wind along the tower makes no drag; the normal part keeps its direction
    f = tower_drag_per_length(node, rho, {6, -8, 3}, {0, 0, 0}, z);
    CHECK(f[0] == doctest::Approx(0.5 * rho * 0.9 * 5 * 10 * 6));
    CHECK(f[1] == doctest::Approx(0.5 * rho * 0.9 * 5 * 10 * -8));
    CHECK(f[2] == 0);
    // a node moving downwind sees less wind; one moving upwind more
    f = tower_drag_per_length(node, rho, {8, 0, 0}, {0.5, 0, 0}, z);
    CHECK(f[0] == doctest::Approx(0.5 * rho * 0.9 * 5 * 7.5 * 7.5));
    f = tower_drag_per_length(node, rho, {1, 0, 0}, {3, 0, 0}, z);
    CHECK(f[0] == doctest::Approx(-0.5 * rho * 0.9 * 5 * 4));
    // a leaning node: only the part of the wind normal to its axis
    const double lean = 0.2;
    const Vec3 axis{std::sin(lean), 0, std::cos(lean)};
    f = tower_drag_per_length(node, rho, {8, 0, 0}, {0, 0, 0}, axis);
    const double normal = 8 * std::cos(lean);
    CHECK(std::hypot(f[0], f[2]) == doctest::Approx(0.5 * rho * 0.9 * 5 * normal * normal));
    CHECK(f[0] * axis[0] + f[2] * axis[2] == doctest::Approx(0.0).scale(1));
    CHECK(f[0] > 0);

    // every node of a state at once
    const std::vector<TowerNode> table{{0, 6, 1, 0.1}, {50, 5, 0.8, 0.1}};
    TowerState state = undeflected_tower(table, {0, 0, 0});
    state.wind = {{8, 0, 0}, {10, 0, 0}};
    Vec3 forces[2];
    tower_drag(table, state, rho, forces);
    CHECK(forces[0][0] == doctest::Approx(0.5 * rho * 6 * 64));
    CHECK(forces[1][0] == doctest::Approx(0.5 * rho * 0.8 * 5 * 100));
}

TEST_CASE("tower drag: its moment about the base is what OpenFAST's tower base gains (twr_U8)") {
    // The deck's tower in the 8 m/s wind (no shear): the drag per length at
    // AeroDyn's tower nodes, linear along each element of its line2 mesh,
    // integrated about the base. The tower moves little (TTDspFA varies by
    // mm), so its velocity is left out.
    const std::string dir = std::string(YAMSC_TEST_DATA_DIR) + "/reference/aero/";
    const std::vector<TowerNode> table = tower_reference::five_mw_tower_table();
    TowerState state = undeflected_tower(table, {0, 0, 0});
    for (Vec3& w : state.wind) w = {8, 0, 0};
    std::vector<Vec3> force(table.size());
    tower_drag(table, state, 1.225, force.data());
    double total = 0, moment = 0;
    for (std::size_t e = 0; e + 1 < table.size(); ++e) {
        const double z1 = table[e].elevation, z2 = table[e + 1].elevation, h = z2 - z1;
        const double f1 = force[e][0], f2 = force[e + 1][0];
        total += h * (f1 + f2) / 2;
        moment += h * (f1 * (2 * z1 + z2) + f2 * (z1 + 2 * z2)) / 6;
    }
    CHECK(total == doctest::Approx(16849).epsilon(1e-4)); // 16.8 kN on the whole tower
    const tower_reference::Effect effect =
        tower_reference::effect(dir + "flex_U8.csv", dir + "twr_U8.csv", 60.0);
    // The tower's influence also lowers the mean thrust a little (the blades
    // pass through the slower air before the tower); that change acting at
    // the hub height bounds what else the base moment may gain.
    const double hub_height = 90.0;
    const double other = std::abs(effect.thrust_change) * 1e3 * hub_height;
    CHECK(other < 0.05 * moment);
    CHECK(std::abs(effect.tower_base_moment_change * 1e3 - moment) < other);
}
