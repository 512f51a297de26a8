// The emitted linear model against the emitted nonlinear one: A and B of
// state_space, C and D of output_matrices equal central finite differences of
// rhs and outputs at random operating points; linear() is consistent with
// state_space(); operating_point() follows the parameters (LPV).
#include "generated_model.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace linear_test;

namespace {

/// Largest |a_ij - b_ij| relative to the largest |a| of row i (at least `floor`):
/// rows of A mix quantities of very different sizes (rates and accelerations).
double worst_relative(const std::vector<double>& a, const std::vector<double>& b, int cols,
                      double floor = 1e-12) {
    REQUIRE(a.size() == b.size());
    double worst = 0;
    for (std::size_t r = 0; cols > 0 && r * static_cast<std::size_t>(cols) < a.size(); ++r) {
        double scale = floor;
        for (int c = 0; c < cols; ++c) scale = std::max(scale, std::fabs(a[r * cols + c]));
        for (int c = 0; c < cols; ++c)
            worst = std::max(worst, std::fabs(a[r * cols + c] - b[r * cols + c]) / scale);
    }
    return worst;
}

struct Case {
    const char* model;
    const char* ns;
    double q_range, rate_range, input_scale;
    // Finite differences in u of rhs and outputs reach this (relative) only: the
    // tower's spring and top mass make them sums of 1e7-sized terms.
    double input_tolerance = 1e-7;
};

std::vector<Point> random_points(const GeneratedModel& m, const Case& c, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), factor(0.8, 1.25);
    std::vector<Point> points;
    for (int k = 0; k < count; ++k) {
        Point p;
        for (double d : m.defaults) p.p.push_back(d * factor(rng)); // other parameter sets too
        for (int i = 0; i < m.nq; ++i) p.q.push_back(c.q_range * unit(rng));
        for (int i = 0; i < m.nq; ++i) p.qd.push_back(c.rate_range * unit(rng));
        for (int i = 0; i < m.nu; ++i) p.u.push_back(c.input_scale * unit(rng));
        points.push_back(p);
    }
    return points;
}

/// A, B, C and D of one model against central differences at random points.
void check_case(const Case& c) {
    const std::string model_name = c.model;
    CAPTURE(model_name);
    GeneratedModel m(c.model, c.ns);
    std::vector<Point> points = random_points(m, c, 6, 42);
    if (std::string(c.ns) == "heavy_top")
        for (Point& p : points) p.q[1] = 0.4 + 0.5 * std::fabs(p.q[1]);
    std::vector<Values> values = m.evaluate(points);
    double worst_A = 0, worst_B = 0, worst_C = 0, worst_D = 0, worst_K = 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
        Values& v = values[k];
        const int nq = m.nq, nx = 2 * nq;
        worst_A = std::max(worst_A, worst_relative(v["A"], v["A_fd"], nx));
        if (m.nu > 0) worst_B = std::max(worst_B, worst_relative(v["B"], v["B_fd"], m.nu));
        if (m.ny > 0) {
            worst_C = std::max(worst_C, worst_relative(v["C"], v["C_fd"], nx));
            if (m.nu > 0) worst_D = std::max(worst_D, worst_relative(v["D"], v["D_fd"], m.nu));
        }
        // linear(): M0 * (lower rows of A) = -[K0, C0], M0 * (lower B) = Q0.
        std::vector<double> MA(static_cast<std::size_t>(nq * nx)), KC(MA.size());
        for (int i = 0; i < nq; ++i)
            for (int j = 0; j < nx; ++j) {
                double s = 0;
                for (int l = 0; l < nq; ++l) s += v["M0"][i * nq + l] * v["A"][(nq + l) * nx + j];
                MA[i * nx + j] = s;
                KC[i * nx + j] = j < nq ? -v["K0"][i * nq + j] : -v["C0"][i * nq + j - nq];
            }
        worst_K = std::max(worst_K, worst_relative(KC, MA, nx));
    }
    MESSAGE(std::string(c.ns) << ": worst relative difference A " << worst_A << ", B " << worst_B
                              << ", C " << worst_C << ", D " << worst_D
                              << "; linear vs state_space " << worst_K);
    CHECK(worst_A < 1e-7);
    CHECK(worst_B < c.input_tolerance);
    CHECK(worst_C < 1e-7);
    CHECK(worst_D < c.input_tolerance);
    CHECK(worst_K < 1e-12);
}

} // namespace

TEST_CASE("state_space and output_matrices equal finite differences of rhs and outputs") {
    const Case cases[] = {
        {"models/pendulum.mbd", "pendulum", 2.5, 2, 1},
        {"models/double_pendulum.mbd", "double_pendulum", 2.5, 2, 5},
        // theta stays away from 0, where the top's M is singular.
        {"models/heavy_top.mbd", "heavy_top", 1.2, 3, 1},
        {"models/nrel5mw_land_2dof.mbd", "nrel5mw_land_2dof", 1.0, 1, 1e6},
        {"models/nrel5mw_spar_rigid.mbd", "nrel5mw_spar_rigid", 0.3, 0.5, 1e6},
        {"models/nrel5mw_blade.mbd", "nrel5mw_blade", 2.0, 2, 1e4},
        {"tests/linear/models/pendulum_op.mbd", "pendulum_op", 2.5, 2, 10},
        // Reaction loads read q'' = M^-1 F: C and D chain through dq''/d[x, u].
        {"tests/linear/models/reactions_double_pendulum.mbd", "reactions_double_pendulum", 2.5, 2,
         5},
        {"tests/linear/models/reactions_tower.mbd", "reactions_tower", 0.3, 0.5, 1e5, 1e-5},
    };
    for (const Case& c : cases) check_case(c);
}

TEST_CASE("output_matrices: the rows of section loads (through q'') equal finite differences") {
    // D of the mid-span fore-aft moment is 6e-5 kN m/N, the top force's moment about
    // the gauge nearly cancelled by the tower's inertia: its central difference in
    // u keeps 1e-5 of it only (the analytic row equals it to that).
    check_case({"tests/linear/models/sections_tower.mbd", "sections_tower", 0.3, 0.5, 1e5, 1e-4});
}

TEST_CASE("operating_point: the linearize block as a function of the parameters (LPV)") {
    GeneratedModel m("tests/linear/models/pendulum_op.mbd", "pendulum_op");
    // param order: m, L, g, c, th0, Omega
    REQUIRE(m.np == 6);
    const double mass = m.defaults[0], L = m.defaults[1], g = m.defaults[2], th0 = m.defaults[4];
    REQUIRE(m.op_q.size() == 1);
    CHECK(m.op_q[0] == doctest::Approx(th0).epsilon(1e-15));
    CHECK(m.op_qd[0] == doctest::Approx(0.0));
    CHECK(m.op_u[0] == doctest::Approx(mass * g * L * std::sin(th0)).epsilon(1e-14));
    std::vector<double> p = m.defaults;
    p[4] = 0.7;
    std::vector<double> op = m.operating_point(p);
    CHECK(op[0] == doctest::Approx(0.7).epsilon(1e-15));
    CHECK(op[2] == doctest::Approx(mass * g * L * std::sin(0.7)).epsilon(1e-14));

    // At the point, the pendulum is an equilibrium held by the torque: A has the
    // exact closed form -g/L cos(th0) and -c/(m L^2).
    Point pt{m.defaults, m.op_q, m.op_qd, m.op_u};
    Values v = m.evaluate({pt})[0];
    const double c = m.defaults[3];
    CHECK(v["A"][2] == doctest::Approx(-g / L * std::cos(th0)).epsilon(1e-14));
    CHECK(v["A"][3] == doctest::Approx(-c / (mass * L * L)).epsilon(1e-14));
    CHECK(v["K0"][0] == doctest::Approx(mass * g * L * std::cos(th0)).epsilon(1e-14));
}
