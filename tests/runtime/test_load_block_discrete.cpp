// Discrete states of load blocks (load_block.hpp): held through every stage of a
// step, advanced once per accepted step from the values read at its start and end.
// A free unit mass driven by a block whose load is its discrete state s, advanced
// to s = t_next at each step: the acceleration is t_k over step k, so the exact
// discrete motion is q_{k+1} = q_k + v_k dt + t_k dt^2 / 2, v_{k+1} = v_k + t_k dt,
// which RK4 integrates exactly (a polynomial of degree 2 within each step); ABM4
// against its own integrator stepped by hand with s held and advanced the same way.
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

ModelView free_mass() {
    ModelView v;
    v.nq = v.nu = v.ny = 1;
    v.input_names = {"f"};
    v.output_names = {"q"};
    v.rhs = [](double, const double* x, const double* u, double* xdot) {
        xdot[0] = x[1];
        xdot[1] = u[0];
    };
    v.outputs = [](double, const double* q, const double*, const double*, double* y) {
        y[0] = q[0];
    };
    return v;
}

} // namespace

TEST_CASE("a block's discrete states advance once per step of RK4 and ABM4") {
    for (Method method : {Method::rk4, Method::abm4}) {
        CAPTURE(method_name(method));
        const auto block = std::make_shared<Staircase>();
        const ModelView v = close_blocks(free_mass(), {block});
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
    const ModelView v = close_blocks(free_mass(), {block});
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
