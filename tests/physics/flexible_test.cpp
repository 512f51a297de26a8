// Flexible bodies against the paper's NREL 5-MW numbers (sections 4.3 and 4.4)
// and against conservation of energy.
#include "equations_fixture.hpp"

#include <yamsc/simulation.hpp>

#include <Eigen/Dense>

#include <algorithm>

using namespace yamsc;

namespace {

constexpr double two_pi = 6.283185307179586;

/// M0 and K0 = -dF/dq at rest (q = q' = 0, inputs 0), from the exact equations.
struct Linear {
    Eigen::MatrixXd M, K;
};

Linear at_rest(const symbolic::Equations& eq, const std::map<std::string, double>& params) {
    const auto n = static_cast<std::size_t>(eq.nq());
    std::vector<double> zero(n, 0.0), u(static_cast<std::size_t>(eq.nu()), 0.0);
    Linear lin{Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, n)};
    auto v0 = test::evaluate(eq, zero, zero, u, params);
    for (std::size_t j = 0; j < n; ++j) {
        const double h = 1e-6;
        std::vector<double> qp = zero, qm = zero;
        qp[j] = h;
        qm[j] = -h;
        auto fp = test::evaluate(eq, qp, zero, u, params).F;
        auto fm = test::evaluate(eq, qm, zero, u, params).F;
        for (std::size_t i = 0; i < n; ++i) {
            lin.M(i, j) = v0.M[i][j];
            lin.K(i, j) = -(fp[i] - fm[i]) / (2 * h);
        }
    }
    return lin;
}

/// Undamped natural frequencies [Hz], ascending.
std::vector<double> frequencies(const Linear& lin) {
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (lin.K + lin.K.transpose()),
                                                                 lin.M);
    std::vector<double> f;
    for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i)
        f.push_back(std::sqrt(std::max(es.eigenvalues()(i), 0.0)) / two_pi);
    std::sort(f.begin(), f.end());
    return f;
}

} // namespace

TEST_CASE("2-DOF land-based turbine (paper 4.4): generalized mass, stiffness, frequency") {
    auto eq = test::derive_file("models/nrel5mw_land_2dof.mbd");
    REQUIRE(eq.nq() == 2);
    Linear lin = at_rest(eq, {});
    MESSAGE("M_q = " << lin.M(0, 0) << " kg, K_q = " << lin.K(0, 0) << " N/m");
    CHECK(lin.M(0, 0) == doctest::Approx(4.375e5).epsilon(0.005));
    CHECK(lin.K(0, 0) == doctest::Approx(1.849e6).epsilon(0.005));
    CHECK(lin.M(1, 1) == doctest::Approx(3.86e7).epsilon(1e-9)); // J_xR
    const double f = std::sqrt(lin.K(0, 0) / lin.M(0, 0)) / two_pi;
    MESSAGE("first fore-aft frequency " << f << " Hz (paper and OpenFAST: 0.3272)");
    CHECK(f == doctest::Approx(0.3272).epsilon(0.002));
}

TEST_CASE("NREL 5-MW blade (paper 4.3): frequencies at rest and Southwell coefficients") {
    auto eq = test::derive_file("models/nrel5mw_blade.mbd");
    REQUIRE(eq.nq() == 3);
    auto f0 = frequencies(at_rest(eq, {{"Omega", 0.0}}));
    MESSAGE("at rest: " << f0[0] << ", " << f0[1] << ", " << f0[2] << " Hz");
    CHECK(f0[0] == doctest::Approx(0.68).epsilon(0.05));
    CHECK(f0[1] == doctest::Approx(1.07).epsilon(0.05));
    CHECK(f0[2] == doctest::Approx(1.94).epsilon(0.05));
    // Mode by mode (the diagonal), as the paper does: k = (ω² - ω0²)/Ω² (+1 for edge,
    // whose in-plane motion also softens by -Ω² Me). The paper's values put the blade
    // root on the rotor axis; the 1.5 m hub radius adds the centripetal acceleration of
    // the root, which stiffens every mode a little more (K_gt, eq. C2).
    const double Omega = 12.1 * two_pi / 60;
    auto southwell = [&](double r_hub) {
        Linear rest = at_rest(eq, {{"Omega", 0.0}, {"r_hub", r_hub}});
        Linear spin = at_rest(eq, {{"Omega", Omega}, {"r_hub", r_hub}});
        std::vector<double> k;
        for (int i = 0; i < 3; ++i) {
            double w0 = rest.K(i, i) / rest.M(i, i), w = spin.K(i, i) / spin.M(i, i);
            k.push_back((w - w0) / (Omega * Omega) + (i == 1 ? 1.0 : 0.0));
        }
        return k;
    };
    const double expected[] = {1.7, 1.4, 5.5};
    auto on_axis = southwell(0.0), at_hub = southwell(1.5);
    for (std::size_t i = 0; i < 3; ++i) {
        CAPTURE(i);
        MESSAGE("mode " << i << ": k_Omega = " << on_axis[i] << " (root on the axis), " << at_hub[i]
                        << " (root at the hub radius)");
        CHECK(std::fabs(on_axis[i] / expected[i] - 1) < 0.05);
        CHECK(at_hub[i] > on_axis[i]);
        CHECK(std::fabs(at_hub[i] / on_axis[i] - 1) < 0.06);
    }
}

TEST_CASE("free-floating flexible beam: energy is conserved to the order of the expansion") {
    // Translating freely the equations are exactly conservative. Rotating, the
    // first-order shape integrals (J, Gr to first order in q) neglect terms of
    // order (q/L)^2 of the rotational energy, so the energy error must shrink
    // like the square of the elastic amplitude.
    auto eq = test::derive_file("tests/physics/models/free_beam.mbd");
    auto c = test::compile_model(eq);
    const auto& v = c.view;
    const int nq = v.nq;
    auto relative_drift = [&](double elastic) {
        runtime::SimulationOptions o;
        o.method = runtime::Method::cvode;
        o.rtol = 1e-11;
        o.atol = 1e-11;
        o.t_end = 20;
        o.dt = 0.1;
        // x, y, z, a, b, q1, q2 and their rates.
        o.x0 = {0,   0,    0,   0.1, -0.2, 0.05 * elastic, -0.03 * elastic,
                0.5, -0.2, 0.1, 0.4, 0.6,  0.2 * elastic,  0.1 * elastic};
        REQUIRE(static_cast<int>(o.x0.size()) == 2 * nq);
        auto r = runtime::simulate(v, o);
        auto energy = [&](std::size_t row) {
            return test::kinetic_energy(v, r.time[row], r.state_row(row)) + r.output_row(row)[0];
        };
        const double E0 = energy(0);
        double drift = 0;
        for (std::size_t i = 0; i < r.rows(); ++i)
            drift = std::max(drift, std::fabs(energy(i) - E0));
        MESSAGE("elastic amplitude x" << elastic << ": energy " << E0 << " J, relative drift "
                                      << drift / E0);
        return drift / E0;
    };
    const double full = relative_drift(1.0), half = relative_drift(0.5);
    CHECK(full < 1e-5);
    CHECK(half < 0.35 * full); // second order in the elastic amplitude
}

TEST_CASE("tower with a top mass on its node: exactly conservative with exact slopes") {
    // Node kinematics (deflection, second-order shortening, exact slope rotation) and
    // the tower's own geometric stiffening (Ct1 with md(q)) form a Lagrangian system.
    auto eq = test::derive_file("tests/physics/models/tower_top_mass.mbd");
    auto c = test::compile_model(eq);
    const auto& v = c.view;
    runtime::SimulationOptions o;
    o.method = runtime::Method::cvode;
    o.rtol = 1e-12;
    o.atol = 1e-12;
    o.t_end = 20;
    o.dt = 0.05;
    o.x0 = {0.8, 0.0};
    auto r = runtime::simulate(v, o);
    auto energy = [&](std::size_t row) {
        return test::kinetic_energy(v, r.time[row], r.state_row(row)) + r.output_row(row)[0];
    };
    // Scale: the oscillation's energy, Ke q0^2 / 2 (E0 holds a large constant potential).
    const double E0 = energy(0), swing = 0.5 * (4 * 5e8 / (20.0 * 20 * 20)) * 0.8 * 0.8;
    double drift = 0, q_min = 0;
    for (std::size_t i = 0; i < r.rows(); ++i) {
        drift = std::max(drift, std::fabs(energy(i) - E0));
        q_min = std::min(q_min, r.state_row(i)[0]);
    }
    MESSAGE("energy drift " << drift << " J (E0 = " << E0 << " J)");
    CHECK(q_min < -0.5); // it oscillates
    CHECK(drift < 1e-7 * swing);
}
