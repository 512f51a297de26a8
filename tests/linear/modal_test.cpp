// The emitted linear model in use: the tower frequency of the 2-DOF land-based
// turbine (paper section 4.4), and linear simulations that follow nonlinear
// ones near an equilibrium.
#include "equations_fixture.hpp"
#include "generated_model.hpp"

#include <yamsc/modal.hpp>
#include <yamsc/simulation.hpp>

#include <doctest/doctest.h>

using namespace linear_test;

TEST_CASE("nrel5mw_land_2dof: the tower fore-aft frequency from state_space is 0.3272 Hz") {
    GeneratedModel m("models/nrel5mw_land_2dof.mbd", "nrel5mw_land_2dof");
    Values v = m.evaluate({{m.defaults, m.op_q, m.op_qd, m.op_u}})[0];
    std::vector<yamsc::runtime::Mode> modes = yamsc::runtime::modal_analysis(v["A"], m.nq);
    REQUIRE(modes.size() == 2);
    CHECK(modes[0].rigid_body); // the free rotor azimuth
    const double f = modes[1].freq_hz;
    MESSAGE("tower fore-aft frequency " << f << " Hz (paper: 0.3272 Hz), " << 100 * (f / 0.3272 - 1)
                                        << " %");
    CHECK(f == doctest::Approx(0.3272).epsilon(0.002));
}

namespace {

/// x' = A x + B du integrated with RK4 (the linear model in deviations).
std::vector<std::vector<double>> linear_run(const std::vector<double>& A, int nx,
                                            std::vector<double> x, double dt, int steps) {
    auto f = [&](const std::vector<double>& y) {
        std::vector<double> d(static_cast<std::size_t>(nx), 0.0);
        for (int i = 0; i < nx; ++i)
            for (int j = 0; j < nx; ++j) d[i] += A[static_cast<std::size_t>(i * nx + j)] * y[j];
        return d;
    };
    auto axpy = [](const std::vector<double>& y, const std::vector<double>& k, double h) {
        std::vector<double> out = y;
        for (std::size_t i = 0; i < y.size(); ++i) out[i] += h * k[i];
        return out;
    };
    std::vector<std::vector<double>> out{x};
    for (int s = 0; s < steps; ++s) {
        auto k1 = f(x), k2 = f(axpy(x, k1, dt / 2)), k3 = f(axpy(x, k2, dt / 2)),
             k4 = f(axpy(x, k3, dt));
        for (int i = 0; i < nx; ++i) x[i] += dt / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
        out.push_back(x);
    }
    return out;
}

/// Max over time and states of |x_nonlinear - (x0 + dx_linear)| / max |dx_linear|.
double linear_vs_nonlinear(const std::string& model, const std::string& ns,
                           const std::vector<double>& dq) {
    GeneratedModel m(model, ns);
    const int nq = m.nq, nx = 2 * nq;
    Values v = m.evaluate({{m.defaults, m.op_q, m.op_qd, m.op_u}})[0];
    auto eq = yamsc::test::derive_file(model);
    auto compiled = yamsc::test::compile_model(eq);
    yamsc::runtime::SimulationOptions o;
    o.t_end = 10;
    o.dt = 1e-3;
    o.u = m.op_u;
    o.x0 = m.op_q;
    o.x0.insert(o.x0.end(), m.op_qd.begin(), m.op_qd.end());
    std::vector<double> dx(static_cast<std::size_t>(nx), 0.0);
    for (int i = 0; i < nq; ++i) {
        o.x0[i] += dq[i];
        dx[i] = dq[i];
    }
    auto nonlinear = yamsc::runtime::simulate(compiled.view, o);
    const int steps = static_cast<int>(std::lround(o.t_end / o.dt));
    auto linear = linear_run(v["A"], nx, dx, o.dt, steps);
    REQUIRE(nonlinear.rows() == linear.size());
    double worst = 0, amplitude = 0;
    for (std::size_t r = 0; r < linear.size(); ++r)
        for (int i = 0; i < nx; ++i) {
            const double x0 = i < nq ? m.op_q[i] : m.op_qd[i - nq];
            worst = std::max(worst, std::fabs(nonlinear.state_row(r)[i] - x0 - linear[r][i]));
            amplitude = std::max(amplitude, std::fabs(linear[r][i]));
        }
    return worst / amplitude;
}

} // namespace

TEST_CASE("a linear simulation near an equilibrium follows the nonlinear one") {
    // The deviation is second order in the amplitude, so relative to the motion it
    // shrinks in proportion: ~1e-3 at 0.01 rad.
    SUBCASE("pendulum held at 0.4 rad by a torque (operating point from parameters)") {
        double small =
            linear_vs_nonlinear("tests/linear/models/pendulum_op.mbd", "pendulum_op", {0.01});
        double tiny =
            linear_vs_nonlinear("tests/linear/models/pendulum_op.mbd", "pendulum_op", {0.001});
        MESSAGE("pendulum_op: relative deviation " << small << " (0.01 rad), " << tiny
                                                   << " (0.001 rad)");
        CHECK(small < 5e-3);
        CHECK(tiny < 5e-4);
        CHECK(tiny < small / 5); // shrinks with the amplitude: the linear model is exact
    }
    SUBCASE("double pendulum about hanging down") {
        double small =
            linear_vs_nonlinear("models/double_pendulum.mbd", "double_pendulum", {0.01, -0.01});
        MESSAGE("double_pendulum: relative deviation " << small);
        CHECK(small < 2e-3);
    }
}
