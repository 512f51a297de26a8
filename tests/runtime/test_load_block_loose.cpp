// Loose coupling (load_block.hpp, Coupling::loose): a block evaluated once per
// accepted step, at its end, and its loads extrapolated within the next step from
// the last interp_order + 1 steps' (OpenFAST's ModCoupling 1 with InterpOrder).
// A free unit mass driven by a load g(t) of time alone: within step k the mass
// feels the extrapolating polynomial of g, which RK4 integrates exactly, so the
// run's end state has a closed form for each order.
#include "runtime/free_mass.hpp"
#include "yamsc/load_block.hpp"
#include "yamsc/simulation.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

namespace {

using namespace yamsc::runtime;

class TimeLoad final : public LoadBlock {
public:
    explicit TimeLoad(std::function<double(double)> g) : g_(std::move(g)) {
        ports_ = {{0}, {}, {0}};
    }
    const BlockPorts& ports() const override { return ports_; }
    std::vector<std::string> output_names() const override { return {"g"}; }
    void evaluate(double t, const double*, const double*, double* loads, double*,
                  double* out) const override {
        loads[0] = out[0] = g_(t);
        ++evaluations;
    }
    mutable int evaluations = 0;

private:
    std::function<double(double)> g_;
    BlockPorts ports_;
};

/// A block with a continuous state (z' = 0), which cannot couple loosely.
class WithState final : public LoadBlock {
public:
    WithState() { ports_ = {{0}, {}, {0}}; }
    const BlockPorts& ports() const override { return ports_; }
    std::vector<std::string> output_names() const override { return {}; }
    std::vector<std::string> state_names() const override { return {"z"}; }
    void evaluate(double, const double*, const double*, double* loads, double* rates,
                  double*) const override {
        loads[0] = 0;
        rates[0] = 0;
    }

private:
    BlockPorts ports_;
};

/// A spring on the mass: its load reads the motion.
class Spring final : public LoadBlock {
public:
    Spring() { ports_ = {{0}, {}, {0}}; }
    const BlockPorts& ports() const override { return ports_; }
    std::vector<std::string> output_names() const override { return {}; }
    void evaluate(double, const double*, const double* r, double* loads, double*,
                  double*) const override {
        loads[0] = -4.0 * r[0];
    }

private:
    BlockPorts ports_;
};

SimulationResult run(const ModelView& v, Method method, double dt, double t_end) {
    SimulationOptions o;
    o.t_end = t_end;
    o.dt = dt;
    o.method = method;
    o.x0 = {0.0, 0.0};
    o.u = {0.0};
    return simulate(v, o);
}

std::vector<double> last_state(const SimulationResult& r) {
    return {r.states.end() - 2, r.states.end()};
}

} // namespace

TEST_CASE("loose coupling holds (order 0) a step's-end load through the next step") {
    const auto g = [](double t) { return 1.0 + 2.0 * t + 3.0 * t * t; };
    const auto block = std::make_shared<TimeLoad>(g);
    const ModelView v = close_blocks(test_free_mass::view(), {block}, {Coupling::loose, 0});
    const double dt = 0.1;
    const int steps = 10;
    const SimulationResult r = run(v, Method::rk4, dt, steps * dt);
    // Within step k the acceleration is g(t_k): q, v as sums.
    double q = 0, qd = 0;
    for (int k = 0; k < steps; ++k) {
        const double a = g(k * dt);
        q += qd * dt + a * dt * dt / 2;
        qd += a * dt;
    }
    const std::vector<double> x = last_state(r);
    CHECK(x[0] == doctest::Approx(q).epsilon(1e-13));
    CHECK(x[1] == doctest::Approx(qd).epsilon(1e-13));
    // Once at the start, then once per step (at its end).
    CHECK(block->evaluations == steps + 1);
    // The rows' block output is g at the row's time, the step's own value.
    const std::size_t col = static_cast<std::size_t>(r.ny - 1);
    for (std::size_t i = 0; i < r.time.size(); ++i)
        CHECK(r.output_row(i)[col] == doctest::Approx(g(r.time[i])));
}

TEST_CASE("loose coupling extrapolates linearly (order 1) from the last two steps") {
    // g linear: step 0 has one value (held), every later step two, whose line is g.
    const auto g = [](double t) { return 1.0 + 2.0 * t; };
    {
        const auto block = std::make_shared<TimeLoad>(g);
        const ModelView v = close_blocks(test_free_mass::view(), {block}, {Coupling::loose, 1});
        const double dt = 0.1, t_end = 1.0;
        const SimulationResult r = run(v, Method::rk4, dt, t_end);
        // Step 0 at g(0), then g exactly from dt to t_end.
        const double q1 = g(0) * dt * dt / 2, v1 = g(0) * dt;
        const auto G = [](double t) { return t + t * t; };                  // int g
        const auto GG = [](double t) { return t * t / 2 + t * t * t / 3; }; // int int g
        const double L = t_end - dt;
        const double v_end = v1 + G(t_end) - G(dt);
        const double q_end = q1 + v1 * L + GG(t_end) - GG(dt) - G(dt) * L;
        const std::vector<double> x = last_state(r);
        CHECK(x[0] == doctest::Approx(q_end).epsilon(1e-12));
        CHECK(x[1] == doctest::Approx(v_end).epsilon(1e-12));
        CHECK(block->evaluations == 11);
    }
    // ABM4 (its predictor's history starts at the held step) evaluates the block
    // as often: once per step.
    const auto block = std::make_shared<TimeLoad>(g);
    run(close_blocks(test_free_mass::view(), {block}, {Coupling::loose, 1}), Method::abm4, 0.1,
        1.0);
    CHECK(block->evaluations == 11);
}

TEST_CASE("loose coupling with quadratic extrapolation approaches tight coupling with the step") {
    // A spring read from the motion: the loose run's error against the tight
    // one falls with dt (the extrapolation's error is O(dt^3) per step).
    const auto spring = std::make_shared<Spring>();
    ModelView base = test_free_mass::view();
    auto error = [&](double dt) {
        const ModelView tight = close_blocks(base, {spring});
        const ModelView loose = close_blocks(base, {spring}, {Coupling::loose, 2});
        SimulationOptions o;
        o.t_end = 2.0;
        o.dt = dt;
        o.method = Method::abm4;
        o.x0 = {1.0, 0.0};
        o.u = {0.0};
        const double a = last_state(simulate(tight, o))[0];
        const double b = last_state(simulate(loose, o))[0];
        CHECK(a == doctest::Approx(std::cos(2.0 * 2.0)).epsilon(1e-4));
        return std::abs(a - b);
    };
    const double coarse = error(0.02), fine = error(0.01);
    CHECK(coarse > 0);
    CHECK(fine < coarse / 3); // second order or better
}

TEST_CASE("a loosely coupled view's Jacobian is the tight one's, and a new run starts anew") {
    const auto spring = std::make_shared<Spring>();
    const ModelView tight = close_blocks(test_free_mass::view(), {spring});
    const ModelView loose = close_blocks(test_free_mass::view(), {spring}, {Coupling::loose, 2});
    const double x[] = {0.3, -0.2}, u[] = {0.0};
    double Jt[4], Jl[4];
    tight.rhs_jacobian(0.0, x, u, Jt);
    loose.rhs_jacobian(0.0, x, u, Jl);
    for (int i = 0; i < 4; ++i) CHECK(Jl[i] == doctest::Approx(Jt[i]));
    CHECK(Jl[2] == doctest::Approx(-4.0));
    // The history belongs to the view: a second run from t = 0 starts it again.
    SimulationOptions o;
    o.t_end = 1.0;
    o.dt = 0.01;
    o.method = Method::abm4;
    o.x0 = {1.0, 0.0};
    o.u = {0.0};
    const std::vector<double> first = last_state(simulate(loose, o));
    const std::vector<double> second = last_state(simulate(loose, o));
    CHECK(first == second);
}

TEST_CASE("a block with continuous states couples tightly only") {
    CHECK_THROWS_AS(
        close_blocks(test_free_mass::view(), {std::make_shared<WithState>()}, {Coupling::loose, 2}),
        std::invalid_argument);
    CHECK_THROWS_AS(close_blocks(test_free_mass::view(),
                                 {std::make_shared<TimeLoad>([](double) { return 0.0; })},
                                 {Coupling::loose, 3}),
                    std::invalid_argument);
}
