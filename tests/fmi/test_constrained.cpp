// A unit of a model with constraint rows runs the constrained view `yamsc sim`
// runs (runtime::constrain): its co-simulation steps, projected after each,
// equal runtime::simulate's, and its outputs include the reactions. The unit
// is a second library in the process beside the double pendulum's.
#include "fmi_host.hpp"
#include "four_bar.hpp"

#include "yamsc/constraints.hpp"
#include "yamsc/simulation.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace fmi_test;

namespace {

template <class F> F* in_four_bar(const char* name) {
    return four_bar_unit().get<F>(name);
}
#define FOUR_BAR(name) in_four_bar<decltype(name)>(#name)

} // namespace

TEST_CASE("fmi3: a constrained model's unit steps as runtime::simulate of the constrained view") {
    const auto view = yamsc::runtime::constrain(
        yamsc::runtime::from_generated<four_bar::Model>(four_bar::Params{}));
    // A consistent start: the crank at 60 degrees turning at 2 rad/s.
    const double pi = 3.14159265358979323846;
    const std::vector<double> u{0.3};
    const auto start =
        yamsc::runtime::consistent_initial_state(view, 0.0, {pi / 3, 0.0, 1.0, 2.0, 0.0, 0.0}, u);

    Log log;
    fmi3Instance in = FOUR_BAR(fmi3InstantiateCoSimulation)(
        "four_bar", "", nullptr, false, false, false, false, nullptr, 0, &log, fmi3_log, nullptr);
    REQUIRE(in);
    // time 0; q 1-3; q' 4-6; q'' 7-9; tau 10; 8 parameters 11-18; outputs from 19.
    const fmi3ValueReference states[] = {1, 2, 3, 4, 5, 6}, tau[] = {10};
    REQUIRE(FOUR_BAR(fmi3SetFloat64)(in, states, 6, start.x.data(), 6) == fmi3OK);
    REQUIRE(FOUR_BAR(fmi3SetFloat64)(in, tau, 1, u.data(), 1) == fmi3OK);
    REQUIRE(FOUR_BAR(fmi3EnterInitializationMode)(in, false, 0.0, 0.0, false, 0.0) == fmi3OK);
    REQUIRE(FOUR_BAR(fmi3ExitInitializationMode)(in) == fmi3OK);
    double t = 0.0, last = 0.0;
    bool event = false, stop = false, early = false;
    for (int k = 0; k < 100; ++k, t += 0.001)
        REQUIRE(FOUR_BAR(fmi3DoStep)(in, t, 0.001, true, &event, &stop, &early, &last) == fmi3OK);

    yamsc::runtime::SimulationOptions o;
    o.t_end = 0.1;
    o.dt = 0.001;
    o.x0 = start.x;
    o.u = u;
    const auto ref = yamsc::runtime::simulate(view, o);
    double x[6];
    REQUIRE(FOUR_BAR(fmi3GetFloat64)(in, states, 6, x, 6) == fmi3OK);
    for (int i = 0; i < 6; ++i) CHECK(std::abs(x[i] - ref.state_row(100)[i]) <= 1e-12);
    CHECK(std::abs(x[0] - start.x[0]) > 0.05); // the crank turned (0.059 rad)

    // The outputs: the model's, then the constrained view's reactions and residuals.
    REQUIRE(view.ny > 2);
    std::vector<fmi3ValueReference> outputs;
    for (int i = 0; i < view.ny; ++i) outputs.push_back(static_cast<fmi3ValueReference>(19 + i));
    std::vector<double> y(static_cast<std::size_t>(view.ny));
    REQUIRE(FOUR_BAR(fmi3GetFloat64)(in, outputs.data(), outputs.size(), y.data(), y.size()) ==
            fmi3OK);
    for (std::size_t i = 0; i < y.size(); ++i)
        CHECK(y[i] == doctest::Approx(ref.output_row(100)[i]).epsilon(1e-9).scale(1.0));
    const fmi3ValueReference method[] = {19 + static_cast<fmi3ValueReference>(view.ny)};
    fmi3Int32 code = -1;
    CHECK(FOUR_BAR(fmi3GetInt32)(in, method, 1, &code, 1) == fmi3OK);
    CHECK(code == 0);
    CHECK(!log.has_error());
    FOUR_BAR(fmi3FreeInstance)(in);
}

TEST_CASE("fmi3: model exchange of a constrained model projects onto the constraints at each "
          "completed step") {
    const auto view = yamsc::runtime::constrain(
        yamsc::runtime::from_generated<four_bar::Model>(four_bar::Params{}));
    const double pi = 3.14159265358979323846;
    const std::vector<double> u{0.0};
    auto x =
        yamsc::runtime::consistent_initial_state(view, 0.0, {pi / 4, 0.0, 1.0, 1.0, 0.0, 0.0}, u).x;

    Log log;
    fmi3Instance in = FOUR_BAR(fmi3InstantiateModelExchange)("four_bar", "", nullptr, false, false,
                                                             &log, fmi3_log);
    REQUIRE(in);
    REQUIRE(FOUR_BAR(fmi3EnterInitializationMode)(in, false, 0.0, 0.0, false, 0.0) == fmi3OK);
    REQUIRE(FOUR_BAR(fmi3ExitInitializationMode)(in) == fmi3OK);
    REQUIRE(FOUR_BAR(fmi3EnterContinuousTimeMode)(in) == fmi3OK);
    // An explicit Euler step of the host drifts off the constraints ...
    double xdot[6];
    REQUIRE(FOUR_BAR(fmi3SetContinuousStates)(in, x.data(), 6) == fmi3OK);
    REQUIRE(FOUR_BAR(fmi3GetContinuousStateDerivatives)(in, xdot, 6) == fmi3OK);
    for (int i = 0; i < 6; ++i) x[static_cast<std::size_t>(i)] += 0.05 * xdot[i];
    REQUIRE(FOUR_BAR(fmi3SetTime)(in, 0.05) == fmi3OK);
    REQUIRE(FOUR_BAR(fmi3SetContinuousStates)(in, x.data(), 6) == fmi3OK);
    const auto drift = yamsc::runtime::constraint_residual_norms(view, 0.05, x.data(), u.data());
    CHECK(drift.position > 1e-6);
    // ... and the completed step moves it back.
    bool event = true, stop = true;
    REQUIRE(FOUR_BAR(fmi3CompletedIntegratorStep)(in, true, &event, &stop) == fmi3OK);
    REQUIRE(FOUR_BAR(fmi3GetContinuousStates)(in, x.data(), 6) == fmi3OK);
    const auto back = yamsc::runtime::constraint_residual_norms(view, 0.05, x.data(), u.data());
    CHECK(back.position <= 1e-12);
    CHECK(back.velocity <= 1e-12);
    CHECK(!log.has_error());
    FOUR_BAR(fmi3FreeInstance)(in);
}
