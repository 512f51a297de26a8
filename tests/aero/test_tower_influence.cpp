// The tower's influence on the blades' wind against the closed forms of
// AeroDyn's models: 2-D potential flow around a cylinder, Bak's correction,
// Powles' and Eames' shadows, and the projection of a point onto the tower.
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "reference_cases.hpp"
#include "tower_reference.hpp"
#include "yamsc/aero/tower_influence.hpp"

using namespace yamsc::aero;

namespace {

constexpr double pi = 3.14159265358979323846;

// A straight vertical tower of constant diameter from z = 0 to 100 m, in a
// uniform wind U along x.
struct Cylinder {
    double diameter = 6, cd = 1.2, ti = 0.1, U = 8;
    std::vector<TowerNode> table;
    TowerState state;
    Cylinder() {
        table = {{0, diameter, cd, ti}, {50, diameter, cd, ti}, {100, diameter, cd, ti}};
        state = undeflected_tower(table, {0, 0, 0});
        for (Vec3& w : state.wind) w = {U, 0, 0};
    }
    Vec3 wind_at(const TowerInfluenceModel& model, const Vec3& point) const {
        return disturbed_wind(model, table, state, point, {U, 0, 0}).wind;
    }
};

const TowerInfluenceModel baseline{TowerPotential::baseline, TowerShadow::none};
const TowerInfluenceModel bak{TowerPotential::bak, TowerShadow::none};
const TowerInfluenceModel powles{TowerPotential::none, TowerShadow::powles};
const TowerInfluenceModel eames{TowerPotential::none, TowerShadow::eames};

// NREL 5-MW's tower table with a Cd and TI that change along it, so that
// their interpolation shows.
std::vector<TowerNode> five_mw_tower() {
    std::vector<TowerNode> t = tower_reference::five_mw_tower_table();
    for (std::size_t j = 0; j < t.size(); ++j) {
        t[j].cd = 1.0 + 0.01 * j;
        t[j].ti = 0.1 + 0.02 * j;
    }
    return t;
}

} // namespace

TEST_CASE("tower potential flow: on the upwind axis the speed is U (1 - (D/2)^2 / x^2)") {
    const Cylinder c;
    for (double x : {-4.0, -6.0, -10.0, -30.0}) {
        const Vec3 w = c.wind_at(baseline, {x, 0, 40});
        const double a = c.diameter / 2;
        CHECK(w[0] == doctest::Approx(c.U * (1 - a * a / (x * x))).epsilon(1e-13));
        CHECK(std::abs(w[1]) < 1e-13);
        CHECK(w[2] == 0);
    }
    // Beside the tower the flow speeds up by the same amount, downwind it
    // slows as upwind (the doublet alone is fore-aft symmetric).
    const double a = c.diameter / 2;
    CHECK(c.wind_at(baseline, {0, 7, 20})[0] == doctest::Approx(c.U * (1 + a * a / 49)));
    CHECK(c.wind_at(baseline, {7, 0, 20})[0] == doctest::Approx(c.U * (1 - a * a / 49)));
}

TEST_CASE("tower potential flow everywhere is the complex potential U (z + a^2 / z)") {
    const Cylinder c;
    const double a = c.diameter / 2;
    for (double x : {-9.0, -3.5, 0.0, 2.0, 11.0})
        for (double y : {-8.0, -1.0, 0.5, 3.3}) {
            const std::complex<double> z(x, y);
            if (std::abs(z) < a * 1.05) continue;
            // u - i v = dW/dz = U (1 - a^2 / z^2)
            const std::complex<double> uv = c.U * (1.0 - a * a / (z * z));
            const Vec3 w = c.wind_at(baseline, {x, y, 60});
            CHECK(w[0] == doctest::Approx(uv.real()).epsilon(1e-12));
            CHECK(w[1] == doctest::Approx(-uv.imag()).epsilon(1e-12));
        }
}

TEST_CASE("Bak's correction: the doublet 0.1 radius downwind plus a source of strength Cd") {
    const Cylinder c;
    const double a = c.diameter / 2;
    for (double x : {-15.0, -7.0, 9.0})
        for (double y : {0.0, 2.0, -5.0}) {
            const double xb = x / a + 0.1, yb = y / a, r2 = xb * xb + yb * yb;
            const double u = (yb * yb - xb * xb) / (r2 * r2) + c.cd * xb / (2 * pi * r2);
            const double v = -2 * xb * yb / (r2 * r2) + c.cd * yb / (2 * pi * r2);
            const Vec3 w = c.wind_at(bak, {x, y, 70});
            CHECK(w[0] == doctest::Approx(c.U * (1 + u)).epsilon(1e-13));
            CHECK(w[1] == doctest::Approx(c.U * v).epsilon(1e-12));
        }
    // On the upwind axis at 10 radii: 1 - 1/9.9^2 - Cd / (2 pi 9.9).
    CHECK(c.wind_at(bak, {-10 * a, 0, 30})[0] ==
          doctest::Approx(c.U * (1 - 1 / (9.9 * 9.9) - c.cd / (2 * pi * 9.9))));
}

TEST_CASE(
    "Powles' shadow: depth Cd / sqrt(r), half width sqrt(r), a cos^2 profile, downwind only") {
    const Cylinder c;
    const double a = c.diameter / 2;
    const double xb = 9;
    // centre line: depth Cd / sqrt(9) = 0.4
    CHECK(c.wind_at(powles, {xb * a, 0, 50})[0] == doctest::Approx(c.U * (1 - c.cd / 3)));
    // across: r = |(9, y)|, half width r^(1/2)
    for (double yb : {0.5, 1.5, 2.5}) {
        const double width = std::sqrt(std::hypot(xb, yb));
        const double cosine = std::cos(pi / 2 * yb / width);
        const Vec3 w = c.wind_at(powles, {xb * a, yb * a, 50});
        CHECK(w[0] == doctest::Approx(c.U * (1 - c.cd / width * cosine * cosine)));
        CHECK(w[1] == doctest::Approx(0.0));
    }
    const double edge = std::sqrt(std::hypot(xb, 3.1)); // 3.1 > sqrt(|(9, 3.1)|) = 3.085
    CHECK(edge < 3.1);
    CHECK(c.wind_at(powles, {xb * a, 3.1 * a, 50})[0] == doctest::Approx(c.U));
    // no shadow upwind
    CHECK(c.wind_at(powles, {-xb * a, 0, 50})[0] == doctest::Approx(c.U));
    // close behind the tower the deficit is limited to half the wind
    CHECK(c.wind_at(powles, {1.5 * a, 0, 50})[0] == doctest::Approx(c.U * 0.5));
}

TEST_CASE("Eames' shadow: a Gaussian of width TI x and area Cd") {
    const Cylinder c;
    const double a = c.diameter / 2;
    const double xb = 20, spread = c.ti * xb;
    const double peak = c.cd / (spread * std::sqrt(2 * pi));
    CHECK(c.wind_at(eames, {xb * a, 0, 50})[0] == doctest::Approx(c.U * (1 - peak)));
    CHECK(c.wind_at(eames, {xb * a, spread * a, 50})[0] ==
          doctest::Approx(c.U * (1 - peak * std::exp(-0.5))));
    CHECK(c.wind_at(eames, {-xb * a, 0, 50})[0] == doctest::Approx(c.U));
    // potential flow and shadow add
    const TowerInfluenceModel both{TowerPotential::baseline, TowerShadow::eames};
    const double yb = 1;
    const double r2 = xb * xb + yb * yb;
    const double expected =
        (yb * yb - xb * xb) / (r2 * r2) - peak * std::exp(-0.5 * (yb / spread) * (yb / spread));
    CHECK(c.wind_at(both, {xb * a, yb * a, 50})[0] == doctest::Approx(c.U * (1 + expected)));
}

TEST_CASE(
    "tower projection: properties interpolated along the element, the taper beyond the ends") {
    const std::vector<TowerNode> table = five_mw_tower();
    TowerState state = undeflected_tower(table, {0, 0, 0});
    for (Vec3& w : state.wind) w = {10, 0, 0};

    // a point a third of the way up element 4 (34.105 .. 42.633 m)
    const double z = 34.105 + (42.633 - 34.105) / 3;
    TowerProjection p = project_onto_tower(table, state, {-12, 3, z});
    CHECK(p.on_element);
    CHECK(p.index == 4);
    CHECK(p.fraction == doctest::Approx(1.0 / 3));
    CHECK(p.diameter == doctest::Approx(5.148 + (4.935 - 5.148) / 3));
    CHECK(p.cd == doctest::Approx(1.04 + 0.01 / 3));
    CHECK(p.ti == doctest::Approx(0.18 + 0.02 / 3));
    CHECK(p.w == doctest::Approx(10));
    CHECK(p.xbar == doctest::Approx(-12 * 2 / p.diameter));
    CHECK(p.ybar == doctest::Approx(3 * 2 / p.diameter));
    CHECK(p.zbar == 0);
    CHECK(p.clearance == doctest::Approx(std::hypot(12, 3) - p.diameter / 2));
    CHECK(p.disturbs);

    // above the top by half a radius: the top node, the influence tapered by cos(pi/4)
    const double top = 87.6, radius = 3.87 / 2;
    p = project_onto_tower(table, state, {-6, 0, top + radius / 2});
    CHECK_FALSE(p.on_element);
    CHECK(p.index == 11);
    CHECK(p.zbar == doctest::Approx(0.5));
    CHECK(p.xbar == doctest::Approx(-6 / radius / std::cos(pi / 4)));
    const TowerInfluenceModel model{TowerPotential::baseline, TowerShadow::none};
    const double xb = p.xbar;
    CHECK(disturbed_wind(model, table, state, {-6, 0, top + radius / 2}, {10, 0, 0}).wind[0] ==
          doctest::Approx(10 * (1 - 1 / (xb * xb))));
    // a radius or more above the top (or below the base): the wind is left alone
    CHECK(disturbed_wind(model, table, state, {-6, 0, top + 1.01 * radius}, {10, 0, 0}).wind[0] ==
          10);
    CHECK(disturbed_wind(model, table, state, {-6, 0, -3.01}, {10, 0, 0}).wind[0] == 10);
    // just above the top within single-precision rounding the top element is used
    p = project_onto_tower(table, state, {-6, 0, top + 2e-6});
    CHECK(p.on_element);
    CHECK(p.index == 10);
    CHECK(p.fraction == 1);
}

TEST_CASE("tower influence: far away and inside the wall the wind is left alone") {
    const Cylinder c;
    CHECK(c.wind_at(baseline, {-(20 * 6 + 3.01), 0, 50})[0] == c.U); // clearance > 20 D
    CHECK(c.wind_at(baseline, {-(20 * 6 + 2.99), 0, 50})[0] < c.U);  // just inside 20 D
    CHECK(c.wind_at(baseline, {-3.05, 0, 50})[0] == c.U);            // clearance < 0.01 D
    const DisturbedWind inside = disturbed_wind(baseline, c.table, c.state, {-1, 0, 50}, {8, 0, 0});
    CHECK(inside.projection.clearance < 0); // a tower strike, for the caller to report
    CHECK(inside.wind[0] == 8);
}

TEST_CASE("tower influence: symmetric about the wind's plane and invariant under rotation") {
    const Cylinder c;
    const TowerInfluenceModel model{TowerPotential::bak, TowerShadow::powles};
    for (double y : {0.7, 4.0, 9.0}) {
        const Vec3 left = c.wind_at(model, {12, y, 50});
        const Vec3 right = c.wind_at(model, {12, -y, 50});
        CHECK(left[0] == doctest::Approx(right[0]).epsilon(1e-14));
        CHECK(left[1] == doctest::Approx(-right[1]).epsilon(1e-14));
    }

    // The whole scene (a leaning, bent tower, the wind, the point) turned
    // about an arbitrary axis gives the same disturbed wind, turned.
    const std::vector<TowerNode> table = five_mw_tower();
    TowerState state = undeflected_tower(table, {1, -2, 0});
    for (std::size_t j = 0; j < table.size(); ++j) {
        const double h = table[j].elevation / 87.6;
        state.position[j][0] += 0.4 * h * h;
        state.position[j][1] += 0.1 * h;
        state.wind[j] = {9, 1.5, 0.3};
        state.velocity[j] = {0.2 * h, -0.05 * h, 0};
    }
    for (std::size_t j = 0; j < table.size(); ++j) {
        const std::size_t k = j + 1 < table.size() ? j + 1 : j, i = k == j ? j - 1 : j;
        Vec3 d{state.position[k][0] - state.position[i][0],
               state.position[k][1] - state.position[i][1],
               state.position[k][2] - state.position[i][2]};
        const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        state.axis[j] = {d[0] / n, d[1] / n, d[2] / n};
    }
    const double angle = 0.7, s = std::sin(angle), co = std::cos(angle);
    const Vec3 k{1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
    auto turn = [&](const Vec3& v) { // Rodrigues
        const double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
        const Vec3 kx{k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2],
                      k[0] * v[1] - k[1] * v[0]};
        Vec3 out;
        for (int i = 0; i < 3; ++i) out[i] = v[i] * co + kx[i] * s + k[i] * kv * (1 - co);
        return out;
    };
    TowerState turned = state;
    for (std::size_t j = 0; j < table.size(); ++j) {
        turned.position[j] = turn(state.position[j]);
        turned.axis[j] = turn(state.axis[j]);
        turned.wind[j] = turn(state.wind[j]);
        turned.velocity[j] = turn(state.velocity[j]);
    }
    for (const Vec3& point : {Vec3{-7, 1, 60}, Vec3{8, -1.5, 30}, Vec3{-4, 0.5, 88.5}}) {
        const Vec3 wind{9.2, 1.4, 0.2};
        const Vec3 a = turn(disturbed_wind(model, table, state, point, wind).wind);
        const Vec3 b = disturbed_wind(model, table, turned, turn(point), turn(wind)).wind;
        CHECK(disturbed_wind(model, table, state, point, wind).projection.disturbs);
        for (int i = 0; i < 3; ++i) CHECK(a[i] == doctest::Approx(b[i]).epsilon(1e-12));
    }
}

TEST_CASE("tower influence follows the wind relative to the moving tower") {
    // a tower moving downwind at 2 m/s in 10 m/s sees 8 m/s: the disturbance
    // is that of 8 m/s, added to the 10 m/s undisturbed wind
    const Cylinder c;
    TowerState moving = c.state;
    for (std::size_t j = 0; j < moving.wind.size(); ++j) {
        moving.wind[j] = {10, 0, 0};
        moving.velocity[j] = {2, 0, 0};
    }
    const Vec3 point{-8, 2, 50};
    const Vec3 w = disturbed_wind(baseline, c.table, moving, point, {10, 0, 0}).wind;
    const Vec3 still = disturbed_wind(baseline, c.table, c.state, point, {8, 0, 0}).wind;
    CHECK(w[0] == doctest::Approx(still[0] + 2));
    CHECK(w[1] == doctest::Approx(still[1]));

    // many points at once: the same as one at a time, and the least clearance
    const Vec3 points[] = {{-8, 2, 50}, {-5, 0, 20}, {4, 1, 70}};
    Vec3 winds[] = {{8, 0, 0}, {8, 0, 0}, {8, 0, 0}};
    const double least = disturb_winds(powles, c.table, c.state, points, winds, 3);
    CHECK(least == doctest::Approx(std::sqrt(17.0) - 3)); // the point 1 m beside 4 m behind
    for (int i = 0; i < 3; ++i)
        CHECK(winds[i][0] ==
              disturbed_wind(powles, c.table, c.state, points[i], {8, 0, 0}).wind[0]);
    CHECK(winds[2][0] < 8);
    CHECK(winds[1][0] == 8);
}

TEST_CASE("tower potential flow on the NREL 5-MW rotor: the disk-averaged wind OpenFAST reports") {
    // AeroDyn's RtVAvgxh is the mean over all blade nodes of the disturbed wind
    // (minus the blades' velocity, unchanged on average) along the shaft. The
    // rotor of the deck, turned through a revolution: apex 5.0191 m upwind of
    // the yaw axis along the shaft tilted 5 deg, 1.96256 m above the 87.6 m
    // tower top; precone 2.5 deg upwind; hub radius 1.5 m; AeroDyn's 19 blade
    // nodes; the deck's tower table; every tower run of cases.txt: its tower
    // model (TwrPotent, TwrShadow), its wind and its mean deflections (its last
    // 20 s; twr_U8: tower top 0.189 m, blade tip 3.11 m downwind, quadratic
    // shapes; the tip's deflection changes the result by 0.3 %).
    for (const reference_cases::Case& c : reference_cases::cases(reference_cases::Kind::tower)) {
        CAPTURE(c.file);
        const TowerInfluenceModel model{static_cast<TowerPotential>(int(c.number("TwrPotent", 0))),
                                        static_cast<TowerShadow>(int(c.number("TwrShadow", 0)))};
        if (!model.active()) continue; // drag only: no disturbance
        const double from = reference_cases::last_20_s(c);
        const reference_cases::Case base = reference_cases::base_run(c);
        const yamsc::table::Table flex = yamsc::table::read_table(base.path());
        const yamsc::table::Table twr = yamsc::table::read_table(c.path());
        const double U = c.wind;
        const double d2r = pi / 180, tilt = 5 * d2r, cone = 2.5 * d2r;
        const double top = tower_reference::statistics(twr, "TTDspFA_[m]", from).mean;
        const double tip = tower_reference::statistics(twr, "OoPDefl1_[m]", from).mean;
        const std::vector<TowerNode> table = tower_reference::five_mw_tower_table();
        TowerState state = undeflected_tower(table, {0, 0, 0});
        for (std::size_t j = 0; j < table.size(); ++j) {
            state.position[j][0] = top * std::pow(table[j].elevation / 87.6, 2);
            state.wind[j] = {U, 0, 0};
        }
        const double span[] = {0,     1.3667,  4.1,   6.8333,  10.25, 14.35, 18.45,
                               22.55, 26.65,   30.75, 34.85,   38.95, 43.05, 47.15,
                               51.25, 54.6667, 57.4,  60.1333, 61.5};
        const Vec3 shaft{std::cos(tilt), 0, -std::sin(tilt)};
        const Vec3 apex{top - 5.0191 * std::cos(tilt), 0, 87.6 + 1.96256 + 5.0191 * std::sin(tilt)};
        const int steps = 720;
        double sum = 0;
        for (int k = 0; k < steps; ++k)
            for (int blade = 0; blade < 3; ++blade) {
                const double azimuth = 2 * pi * (k + blade * steps / 3.0) / steps;
                const Vec3 radial{std::cos(azimuth) * std::sin(tilt), std::sin(azimuth),
                                  std::cos(azimuth) * std::cos(tilt)};
                for (double s : span) {
                    const double r = 1.5 + s, deflection = tip * (s / 61.5) * (s / 61.5);
                    Vec3 p;
                    for (int i = 0; i < 3; ++i)
                        p[i] = apex[i] +
                               r * (std::cos(cone) * radial[i] - std::sin(cone) * shaft[i]) +
                               deflection * shaft[i];
                    const Vec3 w = disturbed_wind(model, table, state, p, {U, 0, 0}).wind;
                    sum += (w[0] - U) * shaft[0] + w[1] * shaft[1] + w[2] * shaft[2];
                }
            }
        const double change = sum / (steps * 3 * 19);

        // OpenFAST's change (tower run less its flexible run) over the last 20 s,
        // and how much it moves between the two 10-s halves: rows every 0.1 s
        // sample the 0.3-s dips unevenly, which bounds how well the reference
        // knows it.
        const double reference = tower_reference::effect(flex, twr, from).rotor_wind_change;
        const double spread = tower_reference::change_spread(flex, twr, "RtVAvgxh_[m/s]",
                                                             {from, from + 10, from + 21});
        if (c.file == "twr_U8.csv") CHECK(reference == doctest::Approx(-0.041).epsilon(0.01));
        CHECK(spread < 0.1 * std::abs(reference));
        CHECK(std::abs(change - reference) < spread);
        MESSAGE("disk-averaged wind change: yamsc " << change << " m/s, OpenFAST " << reference
                                                    << " +- " << spread);
    }
}
