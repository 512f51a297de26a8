// The load-block interface: a block with a state integrated with the structure
// against the closed form, the Jacobians of a closed view against central
// differences, and blocks closed in order (one reading another's output).
#include "yamsc/load_block.hpp"
#include "yamsc/simulation.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>

using namespace yamsc::runtime;

namespace {

/// One DOF: a mass m on a spring k, m q'' = f - k q, inputs (f, target),
/// output v = q'.
ModelView mass_on_spring(double m, double k) {
    ModelView v;
    v.nq = 1;
    v.nu = 2;
    v.ny = 1;
    v.dof_names = {"q"};
    v.input_names = {"f", "target"};
    v.output_names = {"v"};
    v.rhs = [=](double, const double* x, const double* u, double* xd) {
        xd[0] = x[1];
        xd[1] = (u[0] - k * x[0]) / m;
    };
    v.rhs_jacobian = [=](double, const double*, const double*, double* J) {
        J[0] = 0, J[1] = 1, J[2] = -k / m, J[3] = 0;
    };
    v.mass_matrix = [=](double, const double*, const double*, double* M) { M[0] = m; };
    v.forcing = [=](double, const double* q, const double*, const double* u, double* F) {
        F[0] = u[0] - k * q[0];
    };
    v.jacobians = [=](double, const double*, const double*, const double*, double* dq, double* dqd,
                      double* du) { dq[0] = -k, dqd[0] = 0, du[0] = 1, du[1] = 0; };
    v.outputs = [](double, const double*, const double* qd, const double*, double* y) {
        y[0] = qd[0];
    };
    return v;
}

/// A first-order lag with a damper: z' = (target - z) / tau, load = z - d v
/// on the input f; its output is z. Derivatives by the interface's central
/// differences.
class Lag final : public LoadBlock {
public:
    Lag(double tau, double d, int v_output, int target_input, int f_input, std::string name)
        : tau_(tau), d_(d), name_(std::move(name)) {
        ports_.outputs_read = {v_output};
        ports_.inputs_read = {target_input};
        ports_.loads = {f_input};
    }
    const BlockPorts& ports() const override { return ports_; }
    std::vector<std::string> output_names() const override { return {name_ + "_z"}; }
    std::vector<std::string> state_names() const override { return {name_ + "_state"}; }
    void evaluate(double, const double* z, const double* r, double* loads, double* rates,
                  double* out) const override {
        loads[0] = z[0] - d_ * r[0];
        rates[0] = (r[1] - z[0]) / tau_;
        out[0] = z[0];
    }

private:
    double tau_, d_;
    std::string name_;
    BlockPorts ports_;
};

std::vector<double> fd_rhs_jacobian(const ModelView& v, const std::vector<double>& x,
                                    const std::vector<double>& u) {
    const int n = v.nx();
    std::vector<double> J(static_cast<std::size_t>(n * n)), fp(x.size()), fm(x.size());
    for (int j = 0; j < n; ++j) {
        const double h = 1e-6 * (1 + std::fabs(x[j]));
        auto xp = x, xm = x;
        xp[j] += h, xm[j] -= h;
        v.rhs(0, xp.data(), u.data(), fp.data());
        v.rhs(0, xm.data(), u.data(), fm.data());
        for (int r = 0; r < n; ++r) J[r * n + j] = (fp[r] - fm[r]) / (2 * h);
    }
    return J;
}

} // namespace

TEST_CASE("a block with a state: integrated with the structure, as the closed form") {
    // m v' = z - d v, z' = (F0 - z)/tau from rest: z = F0 (1 - e^{-t/tau}),
    // v = F0/(m a) (1 - e^{-a t}) - F0/(m (a - s)) (e^{-s t} - e^{-a t}), a = d/m, s = 1/tau.
    const double m = 2.0, d = 3.0, tau = 0.25, F0 = 5.0;
    const ModelView base = mass_on_spring(m, 0.0);
    const ModelView v = close_blocks(base, {std::make_shared<Lag>(tau, d, 0, 1, 0, "lag")});
    CHECK(v.nz == 1);
    CHECK(v.nx() == 3);
    REQUIRE(v.output_names == std::vector<std::string>{"v", "lag_z"});
    CHECK(column_names(v) ==
          std::vector<std::string>{"time", "q", "q'", "lag_state", "v", "lag_z"});
    CHECK_FALSE(v.forcing); // not second order with a state
    SimulationOptions o;
    o.t_end = 2.0;
    o.dt = 1e-3;
    o.x0 = {0.0, 0.0, 0.0};
    o.u = {0.0, F0};
    const SimulationResult r = simulate(v, o);
    const double t = r.time.back(), a = d / m, s = 1 / tau;
    const double z = F0 * (1 - std::exp(-t / tau));
    const double vel = F0 / (m * a) * (1 - std::exp(-a * t)) -
                       F0 / (m * (a - s)) * (std::exp(-s * t) - std::exp(-a * t));
    CHECK(t == doctest::Approx(2.0));
    const double* x = r.state_row(r.rows() - 1);
    CHECK(x[2] == doctest::Approx(z).epsilon(1e-10));
    CHECK(x[1] == doctest::Approx(vel).epsilon(1e-10));
    CHECK(r.output_row(r.rows() - 1)[1] == x[2]);
    CHECK(vel == doctest::Approx(1.53424).epsilon(1e-5)); // the closed form is not trivial
}

TEST_CASE("a closed view's Jacobians equal central differences of its equations") {
    const ModelView base = mass_on_spring(2.0, 7.0);
    SUBCASE("with a state: rhs_jacobian over [q, q', z]") {
        const ModelView v = close_blocks(base, {std::make_shared<Lag>(0.25, 3.0, 0, 1, 0, "lag")});
        const std::vector<double> x{0.3, -0.7, 1.9}, u{0.4, 5.0};
        std::vector<double> J(9);
        v.rhs_jacobian(0, x.data(), u.data(), J.data());
        const std::vector<double> fd = fd_rhs_jacobian(v, x, u);
        // dq''/dq' = -d/m, dq''/dz = 1/m, dz'/dz = -1/tau.
        CHECK(J[1 * 3 + 1] == doctest::Approx(-1.5).epsilon(1e-7));
        CHECK(J[1 * 3 + 2] == doctest::Approx(0.5).epsilon(1e-7));
        CHECK(J[2 * 3 + 2] == doctest::Approx(-4.0).epsilon(1e-7));
        for (int i = 0; i < 9; ++i) CHECK(J[i] == doctest::Approx(fd[i]).epsilon(1e-7).scale(1));
    }
    SUBCASE("without a state: the second-order Jacobians") {
        // A lag with tau -> a damper only: the state is replaced by a constant load.
        class Damper final : public LoadBlock {
        public:
            Damper() { ports_ = {{0}, {1}, {0}}; }
            const BlockPorts& ports() const override { return ports_; }
            std::vector<std::string> output_names() const override { return {"damper_load"}; }
            void evaluate(double, const double*, const double* r, double* loads, double*,
                          double* out) const override {
                loads[0] = out[0] = -4.0 * r[0] * r[0] + r[1];
            }

        private:
            BlockPorts ports_;
        };
        const ModelView v = close_blocks(base, {std::make_shared<Damper>()});
        REQUIRE(v.jacobians);
        const std::vector<double> q{0.3}, qd{-0.7}, u{0.4, 2.0};
        double dq = 0, dqd = 0, du[2] = {0, 0};
        v.jacobians(0, q.data(), qd.data(), u.data(), &dq, &dqd, du);
        CHECK(dq == doctest::Approx(-7.0));
        CHECK(dqd == doctest::Approx(-8.0 * qd[0]).epsilon(1e-7)); // d(-4 v^2)/dv
        CHECK(du[0] == 1.0);                                // the load's channel stays additive
        CHECK(du[1] == doctest::Approx(1.0).epsilon(1e-7)); // target read by the block
        const std::vector<double> x{q[0], qd[0]};
        std::vector<double> J(4);
        v.rhs_jacobian(0, x.data(), u.data(), J.data());
        const std::vector<double> fd = fd_rhs_jacobian(v, x, u);
        for (int i = 0; i < 4; ++i) CHECK(J[i] == doctest::Approx(fd[i]).epsilon(1e-7).scale(1));
    }
}

TEST_CASE("blocks closed in order: the second reads the first's output, states in order") {
    // The second lag follows the first's state (its output lag1_z, output 1 of
    // the view closed by the first) and adds its own to f too.
    const ModelView base = mass_on_spring(2.0, 7.0);
    const ModelView v = close_blocks(base, {std::make_shared<Lag>(0.25, 0.0, 0, 1, 0, "lag1"),
                                            std::make_shared<Lag>(0.5, 1.0, 1, 1, 0, "lag2")});
    CHECK(v.block_state_names == std::vector<std::string>{"lag1_state", "lag2_state"});
    CHECK(v.output_names == std::vector<std::string>{"v", "lag1_z", "lag2_z"});
    // lag2 reads output 1 (lag1_z) as its damper's velocity: load2 = z2 - z1.
    const std::vector<double> x{0.1, 0.2, 3.0, 5.0}, u{1.0, 4.0};
    std::vector<double> xd(4);
    v.rhs(0, x.data(), u.data(), xd.data());
    CHECK(xd[1] == doctest::Approx((1.0 + 3.0 + (5.0 - 3.0) - 7.0 * 0.1) / 2.0));
    CHECK(xd[2] == doctest::Approx((4.0 - 3.0) / 0.25));
    CHECK(xd[3] == doctest::Approx((4.0 - 5.0) / 0.5));
    std::vector<double> J(16);
    v.rhs_jacobian(0, x.data(), u.data(), J.data());
    const std::vector<double> fd = fd_rhs_jacobian(v, x, u);
    for (int i = 0; i < 16; ++i) CHECK(J[i] == doctest::Approx(fd[i]).epsilon(1e-6).scale(1));
}
