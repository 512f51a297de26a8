// Mooring lines on a body: the OC3-Hywind spar's three lines against the
// restoring matrix its definition publishes, the exact pose derivatives
// against central differences, and the loads' balance with the lines.
#include "mooring/oc3_lines.hpp"

#include <yamsc/mooring/mooring_system.hpp>

#include <doctest/doctest.h>

#include <cmath>

using namespace yamsc::runtime::mooring;

namespace {

Mat3 rotation_about(int axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    Mat3 r{1, 0, 0, 0, 1, 0, 0, 0, 1};
    r[3 * i + i] = c;
    r[3 * i + j] = -s;
    r[3 * j + i] = s;
    r[3 * j + j] = c;
    return r;
}

Mat3 multiply(const Mat3& a, const Mat3& b) {
    Mat3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
    return c;
}

// The body's pose moved by dx (3 translations, 3 small rotations about the
// inertial axes applied after the pose's rotation).
Pose moved(const Pose& p, int dof, double amount) {
    Pose q = p;
    if (dof < 3)
        q.position[dof] += amount;
    else
        q.rotation = multiply(rotation_about(dof - 3, amount), p.rotation);
    return q;
}

} // namespace

TEST_CASE("OC3-Hywind: the lines' restoring matrix at rest is the published one") {
    const MooringLoads m = mooring_loads(test::oc3_lines(), Pose{});
    auto k = [&](int i, int j) { return -m.derivative[6 * (i - 1) + (j - 1)]; };
    // Published (NREL/TP-500-47535, section 5.2), four significant digits, from
    // FAST's numerical linearization: its K15 and K51 differ by 0.18 % where
    // the exact matrix is symmetric, so it is good to about 0.2 %.
    CHECK(k(1, 1) == doctest::Approx(41180).epsilon(0.002));
    CHECK(k(2, 2) == doctest::Approx(41180).epsilon(0.002));
    CHECK(k(3, 3) == doctest::Approx(11940).epsilon(0.002));
    CHECK(k(4, 4) == doctest::Approx(311100000).epsilon(0.002));
    CHECK(k(5, 5) == doctest::Approx(311100000).epsilon(0.002));
    CHECK(k(6, 6) == doctest::Approx(11560000).epsilon(0.002));
    CHECK(k(1, 5) == doctest::Approx(-2821000).epsilon(0.003));
    CHECK(k(5, 1) == doctest::Approx(-2816000).epsilon(0.002));
    CHECK(k(2, 4) == doctest::Approx(2821000).epsilon(0.003));
    // The vertical pretension: the suspended lines' weight in water.
    CHECK(-m.force[2] == doctest::Approx(1607000).epsilon(0.001));
    for (int i = 0; i < 2; ++i) CHECK(std::abs(m.force[i]) < 1e-6);
    for (int i = 0; i < 3; ++i) CHECK(std::abs(m.moment[i]) < 1e-4);
    // At rest the matrix is symmetric: the lines are conservative.
    for (int i = 1; i <= 6; ++i)
        for (int j = 1; j < i; ++j) CHECK(std::abs(k(i, j) - k(j, i)) < 1e-12 * k(4, 4));
}

TEST_CASE("the exact pose derivatives equal central differences at a displaced, rotated pose") {
    const auto lines = test::oc3_lines();
    Pose pose;
    pose.position = {12.0, -3.0, 1.5};
    pose.rotation = multiply(rotation_about(2, 0.2),
                             multiply(rotation_about(1, 0.05), rotation_about(0, -0.03)));
    const MooringLoads m = mooring_loads(lines, pose);
    for (int dof = 0; dof < 6; ++dof) {
        const double step = dof < 3 ? 1e-3 : 1e-6;
        const MooringLoads p = mooring_loads(lines, moved(pose, dof, step), &m);
        const MooringLoads n = mooring_loads(lines, moved(pose, dof, -step), &m);
        for (int i = 0; i < 6; ++i) {
            const double plus = i < 3 ? p.force[i] : p.moment[i - 3];
            const double minus = i < 3 ? n.force[i] : n.moment[i - 3];
            CAPTURE(dof);
            CAPTURE(i);
            CHECK(m.derivative[6 * i + dof] ==
                  doctest::Approx((plus - minus) / (2 * step)).epsilon(1e-5).scale(1e-2));
        }
    }
}

TEST_CASE("each line's force points at its anchor and has the catenary's tension") {
    const auto lines = test::oc3_lines();
    Pose pose;
    pose.position = {20.0, 0.0, 0.0}; // surge 20 m: line 1 (downstream anchor) slackens
    const MooringLoads m = mooring_loads(lines, pose);
    for (std::size_t n = 0; n < lines.size(); ++n) {
        const LineState& s = m.lines[n];
        const double dx = lines[n].anchor[0] - s.fairlead[0],
                     dy = lines[n].anchor[1] - s.fairlead[1];
        const double along =
            (s.force_on_body[0] * dx + s.force_on_body[1] * dy) / std::hypot(dx, dy);
        CHECK(along == doctest::Approx(s.solution.fairlead_horizontal).epsilon(1e-14));
        CHECK(std::hypot(s.force_on_body[0], s.force_on_body[1], s.force_on_body[2]) ==
              doctest::Approx(s.tension()).epsilon(1e-14));
    }
    CHECK(m.lines[0].solution.fairlead_horizontal < m.lines[1].solution.fairlead_horizontal);
    CHECK(m.force[0] < 0); // the lines pull the spar back
}
