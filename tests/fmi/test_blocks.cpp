// Load blocks inside a unit: the plan `yamsc fmu` resolves (block_hook) closes
// the runtime's rotor table around the model with the table read from the
// unit's resources, and an instance of such a unit steps the closed view as
// runtime::simulate does.
#include "instance.hpp"
#include "yamsc/fmi/blocks.hpp"
#include "yamsc/performance_table.hpp"
#include "yamsc/rotor_aero.hpp"
#include "yamsc/simulation.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace yamsc;

namespace {

const std::string resources = std::string(YAMSC_TEST_DATA_DIR) + "/rosco/";

/// The tower top x carrying the thrust and the rotor angle driven by the
/// aerodynamic torque against a generator torque (tests/runtime/test_rotor_aero.cpp's
/// model, its damping the parameter c, without Jacobians: the closed view's are
/// then central differences).
runtime::ModelView tower_and_rotor(const double* p) {
    runtime::ModelView v;
    v.nq = 2;
    v.nu = 5;
    v.ny = 2;
    v.dof_names = {"x", "psi"};
    v.input_names = {"V_wind", "pitch", "thrust", "aero_torque", "gen_torque"};
    v.output_names = {"rotor_speed", "hub_shaft_velocity"};
    const double m = 1e5, k = 4e5, c = p[2], J = 4e7;
    v.rhs = [=](double, const double* x, const double* u, double* xd) {
        xd[0] = x[2], xd[1] = x[3];
        xd[2] = (u[2] - k * x[0] - c * x[2]) / m;
        xd[3] = (u[3] - 97 * u[4]) / J;
    };
    v.outputs = [](double, const double*, const double* qd, const double*, double* y) {
        y[0] = qd[1];
        y[1] = qd[0];
    };
    return v;
}

fmi::RotorTablePlan plan() {
    fmi::RotorTablePlan r;
    r.name = "aero";
    r.table = "Cp_Ct_Cq.NREL5MW.txt";
    r.radius_parameter = 0;
    r.density_parameter = 1;
    r.wind = "V_wind";
    r.pitch = "pitch";
    r.thrust = "thrust";
    r.torque = "aero_torque";
    r.speed = "rotor_speed";
    r.hub_velocity = "hub_shaft_velocity";
    return r;
}

const std::vector<double> params{63.0, 1.225, 2e3};

} // namespace

TEST_CASE("fmi blocks: the hook closes the runtime's rotor table read from the resources") {
    const fmi::BlockHook hook = fmi::block_hook(fmi::BlockPlan{{plan()}});
    REQUIRE(hook);
    CHECK(!fmi::block_hook(fmi::BlockPlan{}));
    const runtime::ModelView base = tower_and_rotor(params.data());
    const runtime::ModelView closed = hook(base, resources, params);
    const runtime::ModelView ref = runtime::close_blocks(
        base,
        {runtime::rotor_table_block(runtime::bind_rotor_aero(
            base, runtime::read_performance_table(resources + "Cp_Ct_Cq.NREL5MW.txt"), 63.0, 1.225,
            "V_wind", "pitch", "thrust", "aero_torque", "rotor_speed", "hub_shaft_velocity"))});
    REQUIRE(closed.output_names == ref.output_names);
    CHECK(closed.ny > 2);
    const double x[] = {0.1, 0.0, 0.05, 1.2}, u[] = {11.0, 0.02, 0.0, 0.0, 4e4};
    double a[4], b[4];
    closed.rhs(0.0, x, u, a);
    ref.rhs(0.0, x, u, b);
    for (int i = 0; i < 4; ++i) CHECK(a[i] == b[i]);
    CHECK(a[2] > 0.0); // the thrust pushes the tower downwind

    CHECK_THROWS_WITH_AS(hook(base, "/nonexistent/", params),
                         doctest::Contains("/nonexistent/Cp_Ct_Cq"), std::runtime_error);
    fmi::RotorTablePlan bad = plan();
    bad.density_parameter = 7;
    CHECK_THROWS_WITH_AS(fmi::block_hook(fmi::BlockPlan{{bad}})(base, resources, params),
                         doctest::Contains("density is parameter 7"), std::invalid_argument);
    bad = plan();
    bad.torque = "no_such_input";
    CHECK_THROWS_AS(fmi::block_hook(fmi::BlockPlan{{bad}})(base, resources, params),
                    std::invalid_argument);
}

TEST_CASE(
    "fmi blocks: an instance with a rotor table steps its closed view as runtime::simulate does") {
    fmi::UnitModel unit;
    unit.name = "tower_and_rotor";
    unit.dof_names = {"x", "psi"};
    unit.input_names = {"V_wind", "pitch", "thrust", "aero_torque", "gen_torque"};
    unit.output_names = {"rotor_speed", "hub_shaft_velocity"};
    unit.param_names = {"R", "rho", "c"};
    unit.param_defaults = params;
    unit.make_view = tower_and_rotor;
    unit.settings.step = 0.02;
    unit.settings.initial_state = {0.0, 0.0, 0.0, 1.2};
    unit.settings.close_blocks = fmi::block_hook(fmi::BlockPlan{{plan()}});

    std::vector<std::string> logged;
    fmi::Instance in(
        unit, fmi::Interface::co_simulation, "rotor", resources,
        [&](fmi::Status, const char*, const std::string& m) { logged.push_back(m); }, false);
    // The table has the block's outputs after the model's.
    const auto& table = in.table();
    std::uint32_t thrust = 0;
    for (const auto& v : table)
        if (v.name == "aero_thrust") thrust = v.value_reference;
    REQUIRE(thrust != 0);
    const std::uint32_t wind = 7, gen = 11; // time, 4 states, 2 accelerations, then the inputs
    REQUIRE(table[wind].name == "V_wind");
    REQUIRE(table[gen].name == "gen_torque");
    const double w = 11.0, g = 4e4;
    REQUIRE(in.set_float64(&wind, 1, &w) == fmi::Status::ok);
    REQUIRE(in.set_float64(&gen, 1, &g) == fmi::Status::ok);
    REQUIRE(in.enter_initialization(std::nullopt, 0.0, std::nullopt) == fmi::Status::ok);
    REQUIRE(in.exit_initialization() == fmi::Status::ok);
    for (int k = 0; k < 50; ++k) REQUIRE(in.do_step(k * 0.02, 0.02) == fmi::Status::ok);

    runtime::SimulationOptions o;
    o.t_end = 1.0;
    o.dt = 0.02;
    o.x0 = {0.0, 0.0, 0.0, 1.2};
    o.u = {w, 0.0, 0.0, 0.0, g};
    const runtime::ModelView closed =
        unit.settings.close_blocks(tower_and_rotor(params.data()), resources, params);
    const auto ref = runtime::simulate(closed, o);
    const std::uint32_t states[] = {1, 2, 3, 4};
    double x[4], t_out = 0.0;
    REQUIRE(in.get_float64(states, 4, x) == fmi::Status::ok);
    for (int i = 0; i < 4; ++i)
        CHECK(std::abs(x[i] - ref.state_row(50)[i]) <= 1e-12 * (1.0 + std::abs(x[i])));
    REQUIRE(in.get_float64(&thrust, 1, &t_out) == fmi::Status::ok);
    const auto column = static_cast<std::size_t>(
        std::find(closed.output_names.begin(), closed.output_names.end(), "aero_thrust") -
        closed.output_names.begin());
    CHECK(t_out == doctest::Approx(ref.output_row(50)[column]).epsilon(1e-12));
    CHECK(t_out > 1e5);

    // The closed view's input Jacobian by central differences: d(x'')/d(V_wind) through the thrust.
    const std::uint32_t xdd = 5;
    double seed = 1.0, dxdd = 0.0;
    REQUIRE(in.directional_derivative(&xdd, 1, &wind, 1, &seed, &dxdd, false) == fmi::Status::ok);
    double plus[4], minus[4];
    const double up[] = {w + 1e-4, 0.0, 0.0, 0.0, g}, um[] = {w - 1e-4, 0.0, 0.0, 0.0, g};
    closed.rhs(1.0, x, up, plus);
    closed.rhs(1.0, x, um, minus);
    CHECK(dxdd == doctest::Approx((plus[2] - minus[2]) / 2e-4).epsilon(1e-6));
    CHECK(dxdd > 0.0);
    CHECK(logged.empty());
}
