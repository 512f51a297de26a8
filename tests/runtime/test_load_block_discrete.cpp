// Discrete states of load blocks (load_block.hpp): held through every stage of a
// step, advanced once per accepted step from the values read at its start and end.
// A free unit mass driven by a block whose load is its discrete state s, advanced
// to s = t_next at each step: the acceleration is t_k over step k, so the exact
// discrete motion is q_{k+1} = q_k + v_k dt + t_k dt^2 / 2, v_{k+1} = v_k + t_k dt,
// which RK4 integrates exactly (a polynomial of degree 2 within each step); ABM4
// against its own integrator stepped by hand with s held and advanced the same way.
#include "runtime/free_mass.hpp"
#include "yamsc/abm4.hpp"
#include "yamsc/load_block.hpp"
#include "yamsc/simulation.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace {

using namespace yamsc::runtime;

class Staircase final : public LoadBlock {
public:
    Staircase() { ports_ = {{0}, {}, {0}}; }
    const BlockPorts& ports() const override { return ports_; }
    std::vector<std::string> output_names() const override { return {"s"}; }
    void evaluate(double, const double*, const double*, double* loads, double*,
                  double* out) const override {
        loads[0] = s_;
        out[0] = s_;
    }
    bool has_discrete_states() const override { return true; }
    void update_discrete_states(double t, const double*, const double* r, double t_next,
                                const double*, const double* r_next) const override {
        // Consecutive steps, and the values read at both ends (q at t and t_next).
        CHECK(t == doctest::Approx(last_t_next_));
        reads_ok_ = reads_ok_ && r[0] == q_seen_;
        last_t_next_ = t_next;
        q_seen_ = r_next[0];
        s_ = t_next;
        ++updates_;
    }
    mutable double s_ = 0, last_t_next_ = 0, q_seen_ = 0;
    mutable int updates_ = 0;
    mutable bool reads_ok_ = true;

private:
    BlockPorts ports_;
};

} // namespace

TEST_CASE("a block's discrete states advance once per step of RK4 and ABM4") {
    for (Method method : {Method::rk4, Method::abm4}) {
        CAPTURE(method_name(method));
        const auto block = std::make_shared<Staircase>();
        const ModelView v = close_blocks(test_free_mass::view(), {block});
        REQUIRE(v.update_discrete);
        SimulationOptions o;
        o.t_end = 1.0;
        o.dt = 0.05;
        o.method = method;
        o.x0 = {0.0, 0.0};
        o.u = {0.0};
        const SimulationResult r = simulate(v, o);
        double q = 0, qd = 0;
        const double dt = o.dt;
        if (method == Method::rk4) {
            for (int k = 0; k < 20; ++k) {
                const double s = k * dt;
                q += qd * dt + 0.5 * s * dt * dt;
                qd += s * dt;
            }
        } else {
            double s = 0;
            std::vector<double> x = {0.0, 0.0};
            Abm4Integrator abm4(
                [&s](double, const double* xs, double* xdot) {
                    xdot[0] = xs[1];
                    xdot[1] = s;
                },
                2);
            for (int k = 0; k < 20; ++k) {
                abm4.step(k * dt, dt, x.data(), nullptr);
                s = (k + 1) * dt;
            }
            q = x[0];
            qd = x[1];
            CHECK(std::abs(q - 1.0 / 6.0) < 0.02); // the continuous t^3/6, roughly
        }
        CHECK(block->updates_ == 20);
        CHECK(block->reads_ok_);
        CHECK(r.time.back() == doctest::Approx(1.0));
        CHECK(r.state_row(r.time.size() - 1)[0] == doctest::Approx(q).epsilon(1e-12));
        CHECK(r.state_row(r.time.size() - 1)[1] == doctest::Approx(qd).epsilon(1e-12));
        // The last row's output sees the state advanced to its own time.
        CHECK(r.output_row(r.time.size() - 1)[1] == doctest::Approx(1.0));
    }
}

TEST_CASE("with CVODE a block's discrete states advance between output points") {
    const auto block = std::make_shared<Staircase>();
    const ModelView v = close_blocks(test_free_mass::view(), {block});
    SimulationOptions o;
    o.t_end = 1.0;
    o.dt = 0.05; // the output step: the discrete step
    o.method = Method::cvode;
    o.x0 = {0.0, 0.0};
    o.u = {0.0};
    const SimulationResult r = simulate(v, o);
    CHECK(block->updates_ == 20);
    CHECK(block->reads_ok_);
    CHECK(r.output_row(r.time.size() - 1)[1] == doctest::Approx(1.0));
    // The staircase's motion within CVODE's tolerance of the exact one (1/6 - dt/4 + dt^2/...).
    double q = 0, qd = 0;
    for (int k = 0; k < 20; ++k) {
        q += qd * o.dt + 0.5 * k * o.dt * o.dt * o.dt;
        qd += k * o.dt * o.dt;
    }
    CHECK(r.state_row(r.time.size() - 1)[0] == doctest::Approx(q).epsilon(0.02));
}

#include "yamsc/trim.hpp"

namespace {

/// A spring k pulled by a block whose load lags: without states (a run's start)
/// it is the quasi-steady c q; its discrete state s relaxes towards the steady
/// load g(q) = c_s q + d with time constant tau; with s held, a q other than the
/// one s last saw adds the transient's c_t (q - q_s). Steady operation is
/// k q = c_s q + d + f0: q* = (d + f0) / (k - c_s).
class LaggingLoad final : public LoadBlock {
public:
    static constexpr double c = 50, c_s = 30, c_t = 400, d = 20, tau = 0.3;
    LaggingLoad() { ports_ = {{0}, {}, {0}}; }
    const BlockPorts& ports() const override { return ports_; }
    std::vector<std::string> output_names() const override { return {"s"}; }
    void evaluate(double, const double*, const double* r, double* loads, double*,
                  double* out) const override {
        loads[0] = started_ ? s_ + c_t * (r[0] - q_s_) : c * r[0];
        out[0] = s_;
    }
    bool has_discrete_states() const override { return true; }
    void update_discrete_states(double t, const double*, const double* r, double t_next,
                                const double*, const double*) const override {
        if (!started_) s_ = c * r[0];
        started_ = true;
        s_ += (c_s * r[0] + d - s_) * (1 - std::exp(-(t_next - t) / tau));
        q_s_ = r[0];
    }
    void reset_discrete_states() const override {
        started_ = false;
        s_ = q_s_ = 0;
    }
    mutable bool started_ = false;
    mutable double s_ = 0, q_s_ = 0;

private:
    BlockPorts ports_;
};

/// m q'' = -k q + f + f0 (f the block's load), q the output it reads.
ModelView spring(double k, double f0) {
    ModelView v;
    v.nq = v.nu = v.ny = 1;
    v.dof_names = {"q"};
    v.input_names = {"f"};
    v.output_names = {"q"};
    v.mass_matrix = [](double, const double*, const double*, double* M) { M[0] = 1; };
    v.forcing = [=](double, const double* q, const double*, const double* u, double* F) {
        F[0] = -k * q[0] + u[0] + f0;
    };
    v.jacobians = [=](double, const double*, const double*, const double*, double* dq, double* dqd,
                      double* du) {
        dq[0] = -k;
        dqd[0] = 0;
        du[0] = 1;
    };
    v.outputs = [](double, const double* q, const double*, const double*, double* y) {
        y[0] = q[0];
    };
    return v;
}

} // namespace

TEST_CASE("trim settles a block's discrete states: the point of steady operation, states kept") {
    const double k = 1000, f0 = 500;
    const auto block = std::make_shared<LaggingLoad>();
    const ModelView v = close_blocks(spring(k, f0), {block});
    REQUIRE(v.update_discrete);
    REQUIRE(v.reset_discrete);
    const TrimResult r = trim(v, {0.0}, {0.0}, {0.0}, {false});
    REQUIRE(r.converged);
    const double steady = (LaggingLoad::d + f0) / (k - LaggingLoad::c_s);
    const double quasi_steady = f0 / (k - LaggingLoad::c);
    MESSAGE("trim: q = " << r.q[0] << " in " << r.discrete_passes << " passes (steady " << steady
                         << ", quasi-steady " << quasi_steady << ")");
    CHECK(r.discrete_passes >= 2);
    CHECK(r.q[0] == doctest::Approx(steady).epsilon(1e-9));
    // The block keeps the settled state: its load at the point is the steady one.
    CHECK(block->started_);
    CHECK(block->s_ == doctest::Approx(LaggingLoad::c_s * steady + LaggingLoad::d).epsilon(1e-9));
    CHECK(std::fabs(r.residual[0]) < 1e-6 * f0);
}
