// outputs_from_qdd: the outputs at a given q''. With the q'' of rhs it is the
// generated `outputs` to the last bit, so the fixed-step simulations store
// rows with the q'' their integrator computed at the point, and the values do
// not depend on which path (or which --dt-out) computed them.
#include "equations_fixture.hpp"

#include <yamsc/abm4.hpp>
#include <yamsc/performance_table.hpp>
#include <yamsc/rk4.hpp>
#include <yamsc/rotor_aero.hpp>
#include <yamsc/simulation.hpp>

#include <cstring>
#include <memory>

using namespace yamsc;

namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

bool same_bits(const double* a, const double* b, std::size_t n) {
    return std::memcmp(a, b, n * sizeof(double)) == 0;
}

// The view with its rhs and outputs counted (the same functions otherwise).
struct Counted {
    runtime::ModelView view;
    std::shared_ptr<std::size_t> rhs = std::make_shared<std::size_t>(0),
                                 outputs = std::make_shared<std::size_t>(0);
};

Counted counted(const runtime::ModelView& base, bool with_outputs_from_qdd) {
    Counted c;
    c.view = base;
    c.view.rhs = [f = base.rhs, n = c.rhs](double t, const double* x, const double* u,
                                           double* xdot) {
        ++*n;
        f(t, x, u, xdot);
    };
    c.view.outputs = [f = base.outputs, n = c.outputs](double t, const double* q, const double* qd,
                                                       const double* u, double* y) {
        ++*n;
        f(t, q, qd, u, y);
    };
    if (!with_outputs_from_qdd) c.view.outputs_from_qdd = nullptr;
    return c;
}

} // namespace

TEST_CASE("outputs_from_qdd with the q'' of rhs is outputs, to the last bit") {
    for (const char* model : {"tests/physics/models/reactions_double_pendulum.mbd",
                              "tests/physics/models/reactions_rigid_tower.mbd"}) {
        CAPTURE(model);
        auto c = test::compile_model(test::derive_file(model));
        const runtime::ModelView& v = c.view;
        REQUIRE(v.outputs_from_qdd);
        const auto nq = static_cast<std::size_t>(v.nq), ny = static_cast<std::size_t>(v.ny);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> U(-2.0, 2.0);
        for (int trial = 0; trial < 50; ++trial) {
            std::vector<double> x(2 * nq), u(static_cast<std::size_t>(v.nu) + 1);
            for (double& e : x) e = U(rng);
            for (double& e : u) e = 10 * U(rng);
            const double t = U(rng);
            std::vector<double> xdot(2 * nq), y(ny), y_qdd(ny), y_other(ny);
            v.rhs(t, x.data(), u.data(), xdot.data());
            v.outputs(t, x.data(), x.data() + nq, u.data(), y.data());
            v.outputs_from_qdd(t, x.data(), x.data() + nq, xdot.data() + nq, u.data(),
                               y_qdd.data());
            CHECK(same_bits(y, y_qdd));
            // The reaction loads do read the q'' given.
            std::vector<double> shifted(xdot.begin() + static_cast<std::ptrdiff_t>(nq), xdot.end());
            for (double& a : shifted) a += 1.0;
            v.outputs_from_qdd(t, x.data(), x.data() + nq, shifted.data(), u.data(),
                               y_other.data());
            CHECK_FALSE(same_bits(y, y_other));
        }
    }
}

TEST_CASE("fixed-step rows: the integrator's q'', the same bits at every --dt-out, no extra rhs") {
    auto c = test::compile_model(
        test::derive_file("tests/physics/models/reactions_double_pendulum.mbd"));
    const runtime::ModelView& v = c.view;
    const auto nq = static_cast<std::size_t>(v.nq), ny = static_cast<std::size_t>(v.ny);
    for (runtime::Method method : {runtime::Method::rk4, runtime::Method::abm4}) {
        const std::string name = runtime::method_name(method);
        CAPTURE(name);
        runtime::SimulationOptions o;
        o.method = method;
        o.t_end = 1.0;
        o.dt = 0.01;
        o.x0 = {0.6, -0.3, 0.5, 1.0};
        o.u_of_t = [](double t, double* u) {
            u[0] = std::sin(3 * t);
            u[1] = 2 * std::cos(t);
        };
        const Counted every = counted(v, true), sparse = counted(v, true),
                      fallback = counted(v, false);
        o.dt_out = 0.0;
        const runtime::SimulationResult dense = runtime::simulate(every.view, o);
        const runtime::SimulationResult plain = runtime::simulate(fallback.view, o);
        o.dt_out = 0.04;
        const runtime::SimulationResult coarse = runtime::simulate(sparse.view, o);
        REQUIRE(dense.rows() == 101);
        REQUIRE(coarse.rows() == 26);
        // Every row: the outputs computes the same numbers (the path before
        // outputs_from_qdd, which the view without it still takes).
        CHECK(same_bits(dense.states, plain.states));
        CHECK(same_bits(dense.outputs, plain.outputs));
        for (std::size_t k = 0; k < coarse.rows(); ++k) {
            CHECK(coarse.time[k] == dense.time[4 * k]);
            CHECK(same_bits(coarse.state_row(k), dense.state_row(4 * k), 2 * nq));
            CHECK(same_bits(coarse.output_row(k), dense.output_row(4 * k), ny));
        }
        // A stored row's outputs are `outputs` at its state.
        std::vector<double> u(2), y(ny);
        for (std::size_t k = 0; k < dense.rows(); k += 17) {
            o.u_of_t(dense.time[k], u.data());
            const double* x = dense.state_row(k);
            v.outputs(dense.time[k], x, x + nq, u.data(), y.data());
            CHECK(same_bits(y.data(), dense.output_row(k), ny));
        }
        // The integration alone, without rows: the rows cost one rhs (the
        // last row's) and no call of outputs.
        const Counted bare = counted(v, true);
        if (method == runtime::Method::rk4)
            runtime::simulate_rk4(bare.view, o.x0, o.u_of_t, o.t_end, o.dt, {});
        else
            runtime::simulate_abm4(bare.view, o.x0, o.u_of_t, o.t_end, o.dt, {});
        CHECK(*every.rhs == *bare.rhs + 1);
        CHECK(*sparse.rhs == *bare.rhs + 1);
        CHECK(*every.outputs == 0);
        CHECK(*sparse.outputs == 0);
        CHECK(*fallback.rhs == *bare.rhs);
        CHECK(*fallback.outputs == 101);
        MESSAGE(name << ": " << *bare.rhs << " rhs for 100 steps, " << *every.rhs
                     << " with 101 rows of outputs");
    }
}

TEST_CASE("rotor aero: the loads' speeds without q'', the same bits; rows with rhs's q''") {
    // The block reads the rotor speed and the hub velocity, which do not read
    // q'': it takes them from outputs_from_qdd with q'' unknown (NaN) instead
    // of from outputs, which would solve M q'' = F.
    auto c = test::compile_model(test::derive_file("models/nrel5mw_land_operating.mbd"));
    const runtime::ModelView& v = c.view;
    const std::vector<double> p = c.library->default_params();
    const auto param = [&](const char* name) {
        return p[static_cast<std::size_t>(c.library->param_index(name))];
    };
    const runtime::RotorAero aero = runtime::bind_rotor_aero(
        v, runtime::read_performance_table(test::source_path("models/data/Cp_Ct_Cq.NREL5MW.txt")),
        param("rotor_radius"), param("air_density"), "V_wind", "pitch", "thrust", "aero_torque",
        "rotor_speed", "hub_shaft_velocity");
    runtime::ModelView without = v;
    without.outputs_from_qdd = nullptr;
    const runtime::ModelView closed = runtime::with_rotor_aero(v, aero),
                             before = runtime::with_rotor_aero(without, aero);
    REQUIRE(closed.outputs_from_qdd);
    CHECK_FALSE(before.outputs_from_qdd);
    const auto nq = static_cast<std::size_t>(v.nq), ny = static_cast<std::size_t>(closed.ny);
    auto input = [&](const char* name) {
        for (std::size_t i = 0; i < v.input_names.size(); ++i)
            if (v.input_names[i] == name) return i;
        FAIL("no input " << name);
        return std::size_t{0};
    };
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<double> x(2 * nq), u(static_cast<std::size_t>(v.nu), 0.0);
        for (double& e : x) e = 0.1 * U(rng);
        x[nq + 2] = 1.2 + 0.1 * U(rng); // psi': the rotor turning
        u[input("V_wind")] = 12 + 4 * U(rng);
        u[input("pitch")] = 0.1 + 0.1 * U(rng);
        u[input("gen_torque")] = 4e4 * (1 + 0.1 * U(rng));
        std::vector<double> xdot(2 * nq), xdot_before(2 * nq), y(ny), y_before(ny), y_qdd(ny);
        closed.rhs(0.5, x.data(), u.data(), xdot.data());
        before.rhs(0.5, x.data(), u.data(), xdot_before.data());
        CHECK(same_bits(xdot, xdot_before));
        closed.outputs(0.5, x.data(), x.data() + nq, u.data(), y.data());
        before.outputs(0.5, x.data(), x.data() + nq, u.data(), y_before.data());
        CHECK(same_bits(y, y_before));
        closed.outputs_from_qdd(0.5, x.data(), x.data() + nq, xdot.data() + nq, u.data(),
                                y_qdd.data());
        CHECK(same_bits(y, y_qdd));
    }
}
