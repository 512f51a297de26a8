// Loads linear in the accelerations (LoadBlock::added_mass): a closed view solves
// them with the structure. Against the model with the added mass written into
// its mass matrix: the same q'', mass matrix, outputs and free vibration.
#include "yamsc/load_block.hpp"
#include "yamsc/second_order.hpp"
#include "yamsc/simulation.hpp"

#include <Eigen/Dense>
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

using namespace yamsc::runtime;

namespace {

/// Two masses in a chain, absolute positions x1 = q1 and x2 = q1 + q2, springs
/// k1 (ground to 1) and k2 (1 to 2), and a force f on mass 2 (input 0): the
/// force's generalized-force column is G = (1, 1). M = [[m1 + m2, m2], [m2, m2]]
/// plus `extra` (the model with an added mass written in). Outputs: x2, its
/// acceleration (reads q''), and the force applied (the input).
ModelView chain(double m1, double m2, double k1, double k2, const Eigen::Matrix2d& extra) {
    Eigen::Matrix2d M;
    M << m1 + m2, m2, m2, m2;
    M += extra;
    Eigen::Matrix2d K;
    K << k1, 0, 0, k2;
    auto forcing = [K](const double* q, const double* u) {
        const Eigen::Vector2d qv(q[0], q[1]);
        const Eigen::Vector2d F = -K * qv + Eigen::Vector2d(u[0], u[0]);
        return F;
    };
    ModelView v;
    v.nq = 2;
    v.nu = 1;
    v.ny = 3;
    v.dof_names = {"q1", "q2"};
    v.input_names = {"f"};
    v.output_names = {"x2", "a2", "f_applied"};
    v.rhs = [M, forcing](double, const double* x, const double* u, double* xd) {
        const Eigen::Vector2d a = M.ldlt().solve(forcing(x, u));
        xd[0] = x[2], xd[1] = x[3], xd[2] = a[0], xd[3] = a[1];
    };
    v.mass_matrix = [M](double, const double*, const double*, double* out) {
        for (int i = 0; i < 4; ++i) out[i] = M(i / 2, i % 2);
    };
    v.forcing = [forcing](double, const double* q, const double*, const double* u, double* F) {
        const Eigen::Vector2d f = forcing(q, u);
        F[0] = f[0], F[1] = f[1];
    };
    v.jacobians = [K](double, const double*, const double*, const double*, double* dq, double* dqd,
                      double* du) {
        for (int i = 0; i < 4; ++i) dq[i] = -K(i / 2, i % 2), dqd[i] = 0;
        du[0] = du[1] = 1;
    };
    v.outputs_from_qdd = [](double, const double* q, const double*, const double* qdd,
                            const double* u, double* y) {
        y[0] = q[0] + q[1];
        y[1] = qdd[0] + qdd[1];
        y[2] = u[0];
    };
    v.outputs = [M, forcing](double, const double* q, const double*, const double* u, double* y) {
        const Eigen::Vector2d a = M.ldlt().solve(forcing(q, u));
        y[0] = q[0] + q[1];
        y[1] = a[0] + a[1];
        y[2] = u[0];
    };
    return v;
}

/// A fluid on mass 2: an added mass `a` (its loads are -a x2''), a constant
/// force f0 and a damper c on x2' (read as output 0's rate... here from q'
/// through the ports: it reads x2 only, so the damper is left out).
class Fluid final : public LoadBlock {
public:
    Fluid(double a, double f0) : a_(a), f0_(f0) {
        ports_.outputs_read = {0};
        ports_.loads = {0};
    }
    const BlockPorts& ports() const override { return ports_; }
    std::vector<std::string> output_names() const override { return {"fluid_f0"}; }
    void evaluate(double, const double*, const double*, double* loads, double*,
                  double* out) const override {
        loads[0] = f0_;
        out[0] = f0_;
    }
    bool has_added_mass() const override { return true; }
    void added_mass(double, const double*, const double*, double* A) const override { A[0] = a_; }

private:
    double a_, f0_;
    BlockPorts ports_;
};

const double m1 = 3.0, m2 = 2.0, k1 = 40.0, k2 = 25.0, a = 1.5, f0 = 7.0;

} // namespace

TEST_CASE("an added mass: the closed view moves as the model with it in its mass matrix") {
    const ModelView base = chain(m1, m2, k1, k2, Eigen::Matrix2d::Zero());
    // x2'' = q1'' + q2'': the added mass a on x2 adds a (1, 1)(1, 1)^T to M.
    const ModelView with = chain(m1, m2, k1, k2, Eigen::Matrix2d::Constant(a));
    const ModelView v = close_blocks(base, {std::make_shared<Fluid>(a, f0)});
    const std::vector<double> x{0.3, -0.2, 0.5, 0.7}, u{0.4}, ue{0.4 + f0};

    std::vector<double> xd(4), xd_with(4);
    v.rhs(0, x.data(), u.data(), xd.data());
    with.rhs(0, x.data(), ue.data(), xd_with.data());
    for (int i = 0; i < 4; ++i) CHECK(xd[i] == doctest::Approx(xd_with[i]).epsilon(1e-12));
    CHECK(std::fabs(xd[2] + xd[3]) > 1.0); // a real acceleration, not a trivial zero

    std::vector<double> M(4), M_with(4);
    v.mass_matrix(0, x.data(), u.data(), M.data());
    with.mass_matrix(0, x.data(), u.data(), M_with.data());
    for (int i = 0; i < 4; ++i) CHECK(M[i] == doctest::Approx(M_with[i]).epsilon(1e-12));

    // The loads applied are f0 - a x2'': what the outputs see as the input.
    std::vector<double> y(4);
    v.outputs(0, x.data(), x.data() + 2, u.data(), y.data());
    const double x2dd = xd_with[2] + xd_with[3];
    CHECK(y[1] == doctest::Approx(x2dd).epsilon(1e-12));
    CHECK(y[2] == doctest::Approx(0.4 + f0 - a * x2dd).epsilon(1e-12));
    CHECK(y[3] == f0);
    std::vector<double> y_qdd(4);
    v.outputs_from_qdd(0, x.data(), x.data() + 2, xd.data() + 2, u.data(), y_qdd.data());
    for (int i = 0; i < 4; ++i) CHECK(y_qdd[i] == doctest::Approx(y[i]).epsilon(1e-12));
}

TEST_CASE("an added mass: lin's frequencies are those of M + G A G^T") {
    const ModelView base = chain(m1, m2, k1, k2, Eigen::Matrix2d::Zero());
    const ModelView v = close_blocks(base, {std::make_shared<Fluid>(a, 0.0)});
    const std::vector<double> q0{0, 0}, qd0{0, 0}, u0{0};
    const SecondOrderModel s = second_order_model(v, q0, qd0, u0);
    Eigen::Matrix2d M, K;
    M << m1 + m2 + a, m2 + a, m2 + a, m2 + a;
    K << k1, 0, 0, k2;
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> e(K, M);
    REQUIRE(s.modes.size() == 2);
    for (int i = 0; i < 2; ++i)
        CHECK(s.modes[static_cast<std::size_t>(i)].freq_hz ==
              doctest::Approx(std::sqrt(e.eigenvalues()[i]) / (2 * M_PI)).epsilon(1e-9));
}

TEST_CASE("an added mass: a free vibration under RK4 keeps the energy of the heavier system") {
    const ModelView base = chain(m1, m2, k1, k2, Eigen::Matrix2d::Zero());
    const ModelView v = close_blocks(base, {std::make_shared<Fluid>(a, 0.0)});
    SimulationOptions o;
    o.t_end = 5.0;
    o.dt = 1e-3;
    o.x0 = {0.1, -0.05, 0.0, 0.0};
    o.u = {0.0};
    const SimulationResult r = simulate(v, o);
    Eigen::Matrix2d M, K;
    M << m1 + m2 + a, m2 + a, m2 + a, m2 + a;
    K << k1, 0, 0, k2;
    auto energy = [&](const double* x) {
        const Eigen::Vector2d q(x[0], x[1]), qd(x[2], x[3]);
        return 0.5 * qd.dot(M * qd) + 0.5 * q.dot(K * q);
    };
    const double e0 = energy(r.state_row(0)), e1 = energy(r.state_row(r.rows() - 1));
    CHECK(e0 > 0.1);
    CHECK(e1 == doctest::Approx(e0).epsilon(1e-9));
}
