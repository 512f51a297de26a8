// The tower's own drag (AeroDyn's TwrAero) against its closed form and
// against what OpenFAST's tower base sees when it is switched on (every tower run
// of data/reference/aero/cases.txt against its flexible run, the same flexible
// turbine with and without tower aerodynamics: twr_U8 vs flex_U8 given).
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "reference_cases.hpp"
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

TEST_CASE("tower drag: its velocity Jacobian against central differences") {
    const TowerNode node{40, 5, 0.9, 0.1};
    const double lean = 0.15;
    const Vec3 axis{0, std::sin(lean), std::cos(lean)};
    const Vec3 wind{8, 2, 0.5}, velocity{0.3, -0.4, 0.1};
    const std::array<double, 9> jacobian =
        tower_drag_velocity_jacobian(node, 1.225, wind, velocity, axis);
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j) {
        Vec3 plus = velocity, minus = velocity;
        plus[j] += h;
        minus[j] -= h;
        const Vec3 fp = tower_drag_per_length(node, 1.225, wind, plus, axis);
        const Vec3 fm = tower_drag_per_length(node, 1.225, wind, minus, axis);
        for (int i = 0; i < 3; ++i)
            CHECK(jacobian[3 * i + j] == doctest::Approx((fp[i] - fm[i]) / (2 * h)).epsilon(1e-7));
    }
    // 1-D: d/dv of 1/2 rho Cd D (U - v)^2 is -rho Cd D U: the tower's aerodynamic damping
    const std::array<double, 9> fore_aft =
        tower_drag_velocity_jacobian(node, 1.225, {8, 0, 0}, {0, 0, 0}, {0, 0, 1});
    CHECK(fore_aft[0] == doctest::Approx(-1.225 * 0.9 * 5 * 8));
    CHECK(fore_aft[4] == doctest::Approx(-0.5 * 1.225 * 0.9 * 5 * 8)); // side-side: half
    CHECK(fore_aft[8] == 0);
    CHECK(tower_drag_velocity_jacobian(node, 1.225, {0, 0, 3}, {}, {0, 0, 1}) ==
          std::array<double, 9>{});
}

TEST_CASE("tower drag: its moment about the base is what OpenFAST's tower base gains (twr_U8 "
          "and every tower run held)") {
    // The deck's tower in the run's wind (no shear): the drag per length at
    // AeroDyn's tower nodes, linear along each element of its line2 mesh,
    // integrated about the base. The tower moves little (TTDspFA varies by
    // mm), so its velocity is left out. A run without TwrAero gains none.
    for (const reference_cases::Case& c : reference_cases::cases(reference_cases::Kind::tower)) {
        CAPTURE(c.file);
        const bool drag = c.setting("TwrAero") &&
                          (*c.setting("TwrAero") == "True" || *c.setting("TwrAero") == "true");
        const std::vector<TowerNode> table = tower_reference::five_mw_tower_table();
        TowerState state = undeflected_tower(table, {0, 0, 0});
        for (Vec3& w : state.wind) w = {c.wind, 0, 0};
        std::vector<Vec3> force(table.size());
        tower_drag(table, state, 1.225, force.data());
        double total = 0, moment = 0;
        for (std::size_t e = 0; e + 1 < table.size(); ++e) {
            const double z1 = table[e].elevation, z2 = table[e + 1].elevation, h = z2 - z1;
            const double f1 = force[e][0], f2 = force[e + 1][0];
            total += h * (f1 + f2) / 2;
            moment += h * (f1 * (2 * z1 + z2) + f2 * (z1 + 2 * z2)) / 6;
        }
        // 16.8 kN on the whole tower at 8 m/s, as the wind's square
        CHECK(total == doctest::Approx(16849 * c.wind * c.wind / 64).epsilon(1e-4));
        if (!drag) moment = 0;
        const reference_cases::Case base = reference_cases::base_run(c);
        const tower_reference::Effect effect =
            tower_reference::effect(base.path(), c.path(), reference_cases::last_20_s(c));
        // The tower's influence also lowers the mean thrust a little (the blades
        // pass through the slower air before the tower); that change acting at
        // the hub height bounds what else the base moment may gain.
        const double hub_height = 90.0;
        const double other = std::abs(effect.thrust_change) * 1e3 * hub_height;
        if (drag) CHECK(other < 0.05 * moment);
        CHECK(std::abs(effect.tower_base_moment_change * 1e3 - moment) < other);
    }
}

TEST_CASE("tower loads per length lumped onto the nodes keep the total force and moment") {
    // a leaning, bent line of three nodes; reference lengths 10 and 20 m
    const Vec3 reference[] = {{0, 0, 0}, {0, 0, 10}, {0, 0, 30}};
    const Vec3 position[] = {{0, 0, 0}, {0.1, 0.05, 10}, {0.5, 0.2, 29.99}};
    const Vec3 per_length[] = {{100, 10, 0}, {80, -20, 5}, {40, 30, 0}};
    Vec3 force[3], moment[3];
    lump_line_loads(reference, position, per_length, 3, force, moment);
    // element by element: F1 = L/6 (2 f1 + f2), F2 = L/6 (f1 + 2 f2)
    CHECK(force[0][0] == doctest::Approx(10.0 / 6 * (200 + 80)));
    CHECK(force[1][0] == doctest::Approx(10.0 / 6 * (100 + 160) + 20.0 / 6 * (160 + 40)));
    CHECK(force[2][1] == doctest::Approx(20.0 / 6 * (-20 + 60)));
    // totals: the distributed load, linear on each element, integrated exactly
    // (force over the reference length; moment about the base with the
    // deflected geometry)
    Vec3 total{}, total_moment{};
    Vec3 expected{}, expected_moment{};
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            total[i] += force[j][i];
            total_moment[i] += moment[j][i];
        }
    for (int j = 0; j < 3; ++j) {
        const Vec3& r = position[j];
        total_moment[0] += r[1] * force[j][2] - r[2] * force[j][1];
        total_moment[1] += r[2] * force[j][0] - r[0] * force[j][2];
        total_moment[2] += r[0] * force[j][1] - r[1] * force[j][0];
    }
    const double lengths[] = {10, 20};
    const int steps = 2000; // midpoint rule on each element: exact to 1e-7 here
    for (int e = 0; e < 2; ++e)
        for (int k = 0; k < steps; ++k) {
            const double s = (k + 0.5) / steps, w = lengths[e] / steps;
            Vec3 f, r;
            for (int i = 0; i < 3; ++i) {
                f[i] = (1 - s) * per_length[e][i] + s * per_length[e + 1][i];
                r[i] = (1 - s) * position[e][i] + s * position[e + 1][i];
                expected[i] += w * f[i];
            }
            expected_moment[0] += w * (r[1] * f[2] - r[2] * f[1]);
            expected_moment[1] += w * (r[2] * f[0] - r[0] * f[2]);
            expected_moment[2] += w * (r[0] * f[1] - r[1] * f[0]);
        }
    for (int i = 0; i < 3; ++i) {
        CHECK(total[i] == doctest::Approx(expected[i]).epsilon(1e-12));
        CHECK(total_moment[i] == doctest::Approx(expected_moment[i]).epsilon(1e-6));
    }
    // the couples only redistribute: they sum to zero
    for (int i = 0; i < 3; ++i) CHECK(std::abs(moment[0][i] + moment[1][i] + moment[2][i]) < 1e-9);
    // at the base node, the couple of the first element: L/12 dp x (f1 + f2)
    CHECK(moment[0][0] == doctest::Approx(10.0 / 12 * (0.05 * 5 - 10 * (10 - 20))));
}

TEST_CASE("tower reference: what the tower changes in OpenFAST's flexible turbine at 8 m/s") {
    // The numbers the reference test compares yamsc's effect with (means of
    // the last 20 s, twr_U8 minus flex_U8), checked against an independent
    // reading of the CSVs.
    const std::string dir = std::string(YAMSC_TEST_DATA_DIR) + "/reference/aero/";
    const tower_reference::Effect e =
        tower_reference::effect(dir + "flex_U8.csv", dir + "twr_U8.csv", 60.0);
    CHECK(e.thrust_change == doctest::Approx(-0.3631).epsilon(1e-3));
    CHECK(e.power_change == doctest::Approx(-3206.6).epsilon(1e-3));
    CHECK(e.tower_base_moment_change == doctest::Approx(678.24).epsilon(1e-4));
    CHECK(e.tower_top_change == doctest::Approx(0.0027400).epsilon(1e-3));
    CHECK(e.rotor_wind_change == doctest::Approx(-0.040996).epsilon(1e-3));
    CHECK(e.root_flap_dip == doctest::Approx(-175.34).epsilon(1e-3));
    CHECK(e.thrust_deviation_without == doctest::Approx(0.3347).epsilon(1e-3));
    CHECK(e.thrust_deviation_with == doctest::Approx(2.730).epsilon(1e-3));
}
