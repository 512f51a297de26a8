// The FMI 3.0 functions of a unit, called as a host calls them, against the
// runtime: model exchange's derivatives are the view's rhs, a co-simulation
// step is runtime::simulate's, the directional derivatives the exact Jacobian.
#include "fmi_host.hpp"
#include "pendulum.hpp"

#include "yamsc/fmi/unit.hpp"
#include "yamsc/fmi/variables.hpp"
#include "yamsc/simulation.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace fmi_test;

namespace {

fmi3Instance model_exchange(Log& log, const char* token_ = token) {
    return FMI3(fmi3InstantiateModelExchange)("pendulum", token_, "/nonexistent/resources/", false,
                                              false, &log, fmi3_log);
}

fmi3Instance co_simulation(Log& log) {
    return FMI3(fmi3InstantiateCoSimulation)("pendulum", token, nullptr, false, false, false, false,
                                             nullptr, 0, &log, fmi3_log, nullptr);
}

void set(fmi3Instance in, unsigned vr, double v);

// A co-simulation instance with the inputs u and the method (the step too
// when given, the host's tolerance when given), initialized.
fmi3Instance started(Log& log, const std::vector<double>& u, yamsc::runtime::Method method,
                     double step = 0.0, double tolerance = 0.0) {
    fmi3Instance in = co_simulation(log);
    REQUIRE(in);
    set(in, vr::tau, u[0]);
    set(in, vr::f, u[1]);
    if (step > 0.0) set(in, vr::step, step);
    const fmi3ValueReference m[] = {vr::method};
    const fmi3Int32 code = yamsc::fmi::method_code(method);
    REQUIRE(FMI3(fmi3SetInt32)(in, m, 1, &code, 1) == fmi3OK);
    REQUIRE(FMI3(fmi3EnterInitializationMode)(in, tolerance > 0.0, tolerance, 0.0, false, 0.0) ==
            fmi3OK);
    REQUIRE(FMI3(fmi3ExitInitializationMode)(in) == fmi3OK);
    return in;
}

void initialize(fmi3Instance in) {
    REQUIRE(FMI3(fmi3EnterInitializationMode)(in, false, 0.0, 0.0, false, 0.0) == fmi3OK);
    REQUIRE(FMI3(fmi3ExitInitializationMode)(in) == fmi3OK);
}

void set(fmi3Instance in, unsigned vr, double v) {
    const fmi3ValueReference r[] = {vr};
    REQUIRE(FMI3(fmi3SetFloat64)(in, r, 1, &v, 1) == fmi3OK);
}

double get(fmi3Instance in, unsigned vr) {
    const fmi3ValueReference r[] = {vr};
    double v = NAN;
    REQUIRE(FMI3(fmi3GetFloat64)(in, r, 1, &v, 1) == fmi3OK);
    return v;
}

// A co-simulation run of the unit with steps h to t_end: the states and outputs after each step.
std::vector<std::vector<double>> run(fmi3Instance in, double h, int steps) {
    std::vector<std::vector<double>> rows;
    const fmi3ValueReference vrs[] = {vr::th1,   vr::th2,   vr::th1d, vr::th2d,
                                      vr::x_tip, vr::z_tip, vr::v_tip};
    double t = get(in, vr::time);
    for (int k = 0; k < steps; ++k) {
        fmi3Boolean event = true, stop = true, early = true;
        double last = NAN;
        REQUIRE(FMI3(fmi3DoStep)(in, t, h, true, &event, &stop, &early, &last) == fmi3OK);
        CHECK(!event);
        CHECK(!stop);
        t += h;
        CHECK(last == doctest::Approx(t).epsilon(1e-14));
        std::vector<double> row(7);
        REQUIRE(FMI3(fmi3GetFloat64)(in, vrs, 7, row.data(), 7) == fmi3OK);
        rows.push_back(row);
    }
    return rows;
}

// The reference: runtime::simulate of the view with the same start, inputs and step.
yamsc::runtime::SimulationResult simulate(yamsc::runtime::Method method, double dt, double t_end,
                                          const std::vector<double>& u) {
    yamsc::runtime::SimulationOptions o;
    o.t_end = t_end;
    o.dt = dt;
    o.method = method;
    o.x0 = x_start;
    o.u = u;
    return yamsc::runtime::simulate(pendulum(), o);
}

void check_rows(const std::vector<std::vector<double>>& rows,
                const yamsc::runtime::SimulationResult& ref, std::size_t stride, double tolerance) {
    REQUIRE(ref.rows() == rows.size() * stride + 1);
    double worst = 0.0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const std::size_t r = (k + 1) * stride;
        for (int i = 0; i < 4; ++i)
            worst = std::max(worst, std::abs(rows[k][i] - ref.state_row(r)[i]));
        for (int i = 0; i < 3; ++i)
            worst = std::max(worst, std::abs(rows[k][4 + i] - ref.output_row(r)[i]));
    }
    CHECK(worst <= tolerance);
    MESSAGE("largest difference to runtime::simulate: " << worst);
}

} // namespace

TEST_CASE(
    "fmi3: the unit exports every function of the standard's model exchange and co-simulation") {
    for (const char* name : {"fmi3GetVersion",
                             "fmi3SetDebugLogging",
                             "fmi3InstantiateModelExchange",
                             "fmi3InstantiateCoSimulation",
                             "fmi3InstantiateScheduledExecution",
                             "fmi3FreeInstance",
                             "fmi3EnterInitializationMode",
                             "fmi3ExitInitializationMode",
                             "fmi3EnterEventMode",
                             "fmi3Terminate",
                             "fmi3Reset",
                             "fmi3GetFloat32",
                             "fmi3GetFloat64",
                             "fmi3GetInt8",
                             "fmi3GetUInt8",
                             "fmi3GetInt16",
                             "fmi3GetUInt16",
                             "fmi3GetInt32",
                             "fmi3GetUInt32",
                             "fmi3GetInt64",
                             "fmi3GetUInt64",
                             "fmi3GetBoolean",
                             "fmi3GetString",
                             "fmi3GetBinary",
                             "fmi3GetClock",
                             "fmi3SetFloat32",
                             "fmi3SetFloat64",
                             "fmi3SetInt8",
                             "fmi3SetUInt8",
                             "fmi3SetInt16",
                             "fmi3SetUInt16",
                             "fmi3SetInt32",
                             "fmi3SetUInt32",
                             "fmi3SetInt64",
                             "fmi3SetUInt64",
                             "fmi3SetBoolean",
                             "fmi3SetString",
                             "fmi3SetBinary",
                             "fmi3SetClock",
                             "fmi3GetNumberOfVariableDependencies",
                             "fmi3GetVariableDependencies",
                             "fmi3GetFMUState",
                             "fmi3SetFMUState",
                             "fmi3FreeFMUState",
                             "fmi3SerializedFMUStateSize",
                             "fmi3SerializeFMUState",
                             "fmi3DeserializeFMUState",
                             "fmi3GetDirectionalDerivative",
                             "fmi3GetAdjointDerivative",
                             "fmi3EnterConfigurationMode",
                             "fmi3ExitConfigurationMode",
                             "fmi3GetIntervalDecimal",
                             "fmi3GetIntervalFraction",
                             "fmi3GetShiftDecimal",
                             "fmi3GetShiftFraction",
                             "fmi3SetIntervalDecimal",
                             "fmi3SetIntervalFraction",
                             "fmi3SetShiftDecimal",
                             "fmi3SetShiftFraction",
                             "fmi3EvaluateDiscreteStates",
                             "fmi3UpdateDiscreteStates",
                             "fmi3EnterContinuousTimeMode",
                             "fmi3CompletedIntegratorStep",
                             "fmi3SetTime",
                             "fmi3SetContinuousStates",
                             "fmi3GetContinuousStateDerivatives",
                             "fmi3GetEventIndicators",
                             "fmi3GetContinuousStates",
                             "fmi3GetNominalsOfContinuousStates",
                             "fmi3GetNumberOfEventIndicators",
                             "fmi3GetNumberOfContinuousStates",
                             "fmi3EnterStepMode",
                             "fmi3GetOutputDerivatives",
                             "fmi3DoStep",
                             "fmi3ActivateModelPartition"}) {
        INFO(name);
        CHECK(unit().symbol(name) != nullptr);
    }
    CHECK(std::string(FMI3(fmi3GetVersion)()) == "3.0");
    // Only the standard's functions leave the unit: not the runtime, not the glue.
    CHECK(unit().symbol("_ZN5yamsc3fmi10unit_modelEv") == nullptr);
    CHECK(unit().symbol("_ZN15double_pendulum3rhsEdPKdS1_RKNS_6ParamsEPd") ==
          nullptr); // the model's rhs
    CHECK(unit().symbol("_ZN5yamsc7runtime8simulateERKNS0_9ModelViewERKNS0_"
                        "17SimulationOptionsERKSt8functionIFbddEE") ==
          nullptr); // the runtime's simulate
}

TEST_CASE("fmi3: the value references of the table are the ones the unit reads") {
    const auto view = pendulum();
    yamsc::fmi::UnitLayout layout = yamsc::fmi::layout_of(
        view, {"m1", "m2", "L1", "L2", "g", "k", "c"}, {2.0, 1.0, 1.0, 0.8, 9.81, 5.0, 0.1});
    const auto table = yamsc::fmi::variables(layout);
    REQUIRE(table.size() == 21);
    for (std::size_t k = 0; k < table.size(); ++k) CHECK(table[k].value_reference == k);
    CHECK(table[vr::th1dd].name == "th1''");
    CHECK(table[vr::th1dd].derivative_of == vr::th1d);
    CHECK(table[vr::th1d].derivative_of == vr::th1);
    CHECK(table[vr::tau].causality == yamsc::fmi::Causality::input);
    CHECK(table[vr::c].name == "c");
    CHECK(table[vr::v_tip].name == "v_tip");
    CHECK(table[vr::method].type == yamsc::fmi::ValueType::int32);
    CHECK(table[vr::step].name == "yamsc.step");

    Log log;
    fmi3Instance in = model_exchange(log);
    REQUIRE(in);
    initialize(in);
    CHECK(get(in, vr::th2) == -0.3); // the glue's start state
    CHECK(get(in, vr::th2d) == 0.2);
    CHECK(get(in, vr::m1) == 2.0);    // the model's default
    CHECK(get(in, vr::c) == 0.15);    // the glue's start value
    CHECK(get(in, vr::step) == 0.01); // the glue's setting
    const fmi3ValueReference m[] = {vr::method};
    fmi3Int32 method = -1;
    CHECK(FMI3(fmi3GetInt32)(in, m, 1, &method, 1) == fmi3OK);
    CHECK(method == 0);
    FMI3(fmi3FreeInstance)(in);
}

TEST_CASE("fmi3: model exchange's derivatives and outputs are the view's rhs and outputs") {
    Log log;
    fmi3Instance in = model_exchange(log);
    REQUIRE(in);
    set(in, vr::k, 7.5); // a parameter set before initialization reaches the equations
    initialize(in);
    bool more = true, terminate = true, nominals = true, values = true, next = true;
    double next_time = 1.0;
    CHECK(FMI3(fmi3UpdateDiscreteStates)(in, &more, &terminate, &nominals, &values, &next,
                                         &next_time) == fmi3OK);
    CHECK(!more);
    CHECK(!next);
    CHECK(FMI3(fmi3EnterContinuousTimeMode)(in) == fmi3OK);
    size_t n = 0, ni = 7;
    CHECK(FMI3(fmi3GetNumberOfContinuousStates)(in, &n) == fmi3OK);
    CHECK(FMI3(fmi3GetNumberOfEventIndicators)(in, &ni) == fmi3OK);
    REQUIRE(n == 4);
    CHECK(ni == 0);

    double_pendulum::Params p = parameters();
    p.k = 7.5;
    const auto view = yamsc::runtime::from_generated<double_pendulum::Model>(p);
    const std::vector<double> x{0.9, -1.2, 2.5, -0.7}, u{0.3, -1.1};
    CHECK(FMI3(fmi3SetTime)(in, 0.25) == fmi3OK);
    CHECK(FMI3(fmi3SetContinuousStates)(in, x.data(), 4) == fmi3OK);
    set(in, vr::tau, u[0]);
    set(in, vr::f, u[1]);
    std::vector<double> xdot(4), ref(4), y(3), nominal(4), back(4);
    CHECK(FMI3(fmi3GetContinuousStateDerivatives)(in, xdot.data(), 4) == fmi3OK);
    view.rhs(0.25, x.data(), u.data(), ref.data());
    for (int i = 0; i < 4; ++i)
        CHECK(std::abs(xdot[i] - ref[i]) <= 1e-15 * (1.0 + std::abs(ref[i])));
    CHECK(xdot[2] != 0.0);
    CHECK(get(in, vr::th2dd) == xdot[3]);
    view.outputs(0.25, x.data(), x.data() + 2, u.data(), y.data());
    CHECK(get(in, vr::x_tip) == doctest::Approx(y[0]).epsilon(1e-15));
    CHECK(get(in, vr::v_tip) == doctest::Approx(y[2]).epsilon(1e-15));
    CHECK(get(in, vr::time) == 0.25);
    CHECK(FMI3(fmi3GetContinuousStates)(in, back.data(), 4) == fmi3OK);
    CHECK(back == x);
    CHECK(FMI3(fmi3GetNominalsOfContinuousStates)(in, nominal.data(), 4) == fmi3OK);
    CHECK(nominal == std::vector<double>(4, 1.0));
    bool enter_event = true, stop = true;
    CHECK(FMI3(fmi3CompletedIntegratorStep)(in, true, &enter_event, &stop) == fmi3OK);
    CHECK(!enter_event);
    CHECK(!stop);
    // A tunable parameter changed in Event Mode: the next derivatives are the new model's.
    REQUIRE(FMI3(fmi3EnterEventMode)(in) == fmi3OK);
    set(in, vr::k, 3.0);
    REQUIRE(FMI3(fmi3EnterContinuousTimeMode)(in) == fmi3OK);
    const fmi3ValueReference k[] = {vr::k};
    const double k_again = 4.0;
    CHECK(FMI3(fmi3SetFloat64)(in, k, 1, &k_again, 1) == fmi3Error); // not in Continuous-Time Mode
    p.k = 3.0;
    yamsc::runtime::from_generated<double_pendulum::Model>(p).rhs(0.25, x.data(), u.data(),
                                                                  ref.data());
    CHECK(FMI3(fmi3GetContinuousStateDerivatives)(in, xdot.data(), 4) == fmi3OK);
    for (int i = 0; i < 4; ++i)
        CHECK(std::abs(xdot[i] - ref[i]) <= 1e-15 * (1.0 + std::abs(ref[i])));
    log.messages.clear();
    CHECK(FMI3(fmi3Terminate)(in) == fmi3OK);
    CHECK(!log.has_error());
    FMI3(fmi3FreeInstance)(in);
}

TEST_CASE("fmi3: a co-simulation step is runtime::simulate's (RK4, ABM4, several internal steps)") {
    using yamsc::runtime::Method;
    const std::vector<double> u{0.7, -0.4};
    Log log;
    SUBCASE("RK4, the communication step is the internal step") {
        fmi3Instance in = started(log, u, Method::rk4);
        check_rows(run(in, 0.01, 100), simulate(Method::rk4, 0.01, 1.0, u), 1, 1e-12);
        FMI3(fmi3FreeInstance)(in);
    }
    SUBCASE("RK4, five internal steps per communication step") {
        fmi3Instance in = started(log, u, Method::rk4, 0.002);
        check_rows(run(in, 0.01, 50), simulate(Method::rk4, 0.002, 0.5, u), 5, 1e-12);
        FMI3(fmi3FreeInstance)(in);
    }
    SUBCASE("ABM4: the multistep history carries over between communication steps") {
        fmi3Instance in = started(log, u, Method::abm4);
        const auto rows = run(in, 0.01, 100);
        check_rows(rows, simulate(Method::abm4, 0.01, 1.0, u), 1, 1e-12);
        // Not RK4's numbers: the run did take ABM4 steps.
        CHECK(std::abs(rows.back()[0] - simulate(Method::rk4, 0.01, 1.0, u).state_row(100)[0]) >
              1e-9);
        FMI3(fmi3FreeInstance)(in);
    }
    SUBCASE("CVODE, restarted at each communication point: near RK4 at a small step") {
        fmi3Instance in = started(log, u, Method::cvode, 0.0, 1e-9);
        check_rows(run(in, 0.05, 20), simulate(Method::rk4, 0.001, 1.0, u), 50, 1e-6);
        FMI3(fmi3FreeInstance)(in);
    }
    CHECK(!log.has_error());
}

TEST_CASE(
    "fmi3: a state got and set again repeats the run to the last bit (ABM4's history included)") {
    Log log;
    fmi3Instance in = started(log, {0.0, 0.0}, yamsc::runtime::Method::abm4);
    run(in, 0.01, 30);
    fmi3FMUState state = nullptr;
    REQUIRE(FMI3(fmi3GetFMUState)(in, &state) == fmi3OK);
    REQUIRE(state != nullptr);
    const auto first = run(in, 0.01, 20);
    set(in, vr::tau, 3.0); // changes after the snapshot are undone by setting it
    run(in, 0.01, 5);
    REQUIRE(FMI3(fmi3SetFMUState)(in, state) == fmi3OK);
    CHECK(get(in, vr::time) == doctest::Approx(0.3).epsilon(1e-14));
    CHECK(get(in, vr::tau) == 0.0);
    const auto again = run(in, 0.01, 20);
    CHECK(again == first);
    // A second GetFMUState into the same state overwrites it.
    REQUIRE(FMI3(fmi3GetFMUState)(in, &state) == fmi3OK);
    CHECK(FMI3(fmi3FreeFMUState)(in, &state) == fmi3OK);
    CHECK(state == nullptr);
    size_t size = 0;
    CHECK(FMI3(fmi3SerializedFMUStateSize)(in, state, &size) == fmi3Error);
    CHECK(log.has_error());
    FMI3(fmi3FreeInstance)(in);
}

TEST_CASE("fmi3: directional derivatives are the exact Jacobian, and central differences agree") {
    Log log;
    fmi3Instance in = model_exchange(log);
    REQUIRE(in);
    initialize(in);
    REQUIRE(FMI3(fmi3EnterContinuousTimeMode)(in) == fmi3OK);
    const std::vector<double> x{0.4, 0.8, -1.5, 0.6}, u{0.9, 0.35};
    REQUIRE(FMI3(fmi3SetTime)(in, 0.7) == fmi3OK);
    REQUIRE(FMI3(fmi3SetContinuousStates)(in, x.data(), 4) == fmi3OK);
    set(in, vr::tau, u[0]);
    set(in, vr::f, u[1]);

    const fmi3ValueReference unknowns[] = {vr::th1d,  vr::th2d,  vr::th1dd, vr::th2dd,
                                           vr::x_tip, vr::z_tip, vr::v_tip};
    const fmi3ValueReference knowns[] = {vr::th1, vr::th2, vr::th1d, vr::th2d, vr::tau, vr::f};
    // J column by column (unit seeds), 7 x 6.
    double J[7][6];
    for (int j = 0; j < 6; ++j) {
        double seed[6] = {0, 0, 0, 0, 0, 0}, s[7];
        seed[j] = 1.0;
        REQUIRE(FMI3(fmi3GetDirectionalDerivative)(in, unknowns, 7, knowns, 6, seed, 6, s, 7) ==
                fmi3OK);
        for (int i = 0; i < 7; ++i) J[i][j] = s[i];
    }
    const auto view = pendulum();
    std::vector<double> A(16), C(12), D(6);
    view.rhs_jacobian(0.7, x.data(), u.data(), A.data());
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) CHECK(J[i][j] == A[i * 4 + j]);
    // The outputs' rows are the generated output matrices (the model has no explicit time).
    double_pendulum::output_matrices(x.data(), x.data() + 2, u.data(), parameters(), C.data(),
                                     D.data());
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) CHECK(J[4 + i][j] == C[i * 4 + j]);
        for (int j = 0; j < 2; ++j) CHECK(J[4 + i][4 + j] == D[i * 2 + j]);
    }

    // Central differences of the view's rhs and outputs in every known.
    std::vector<double> v = x;
    v.insert(v.end(), u.begin(), u.end());
    auto values = [&](const std::vector<double>& w) {
        std::vector<double> xdot(4), y(3), out;
        view.rhs(0.7, w.data(), w.data() + 4, xdot.data());
        view.outputs(0.7, w.data(), w.data() + 2, w.data() + 4, y.data());
        out = xdot;
        out.insert(out.end(), y.begin(), y.end());
        return out;
    };
    double worst = 0.0;
    for (int j = 0; j < 6; ++j) {
        const double h = 1e-5;
        auto plus = v, minus = v;
        plus[j] += h;
        minus[j] -= h;
        const auto fp = values(plus), fm = values(minus);
        for (int i = 0; i < 7; ++i) {
            const double fd = (fp[i] - fm[i]) / (2 * h);
            worst = std::max(worst, std::abs(J[i][j] - fd) / (1.0 + std::abs(fd)));
        }
    }
    MESSAGE("largest relative difference to central differences: " << worst);
    CHECK(worst < 1e-8);
    CHECK(J[2][4] != 0.0); // the torque accelerates the first link

    // The adjoint: seed^T J.
    const double seed[7] = {0.1, -0.2, 0.3, 0.5, -0.7, 1.1, 0.13};
    double adjoint[6];
    REQUIRE(FMI3(fmi3GetAdjointDerivative)(in, unknowns, 7, knowns, 6, seed, 7, adjoint, 6) ==
            fmi3OK);
    for (int j = 0; j < 6; ++j) {
        double s = 0.0;
        for (int i = 0; i < 7; ++i) s += seed[i] * J[i][j];
        CHECK(adjoint[j] == doctest::Approx(s).epsilon(1e-14));
    }
    // A parameter is not a known.
    const fmi3ValueReference parameter[] = {vr::m1};
    double one = 1.0, out[7];
    CHECK(FMI3(fmi3GetDirectionalDerivative)(in, unknowns, 7, parameter, 1, &one, 1, out, 7) ==
          fmi3Error);
    FMI3(fmi3FreeInstance)(in);
}

TEST_CASE("fmi3: the state machine refuses what the standard does not allow, with a logged error") {
    Log log;
    CHECK(model_exchange(log, "{another-build}") == nullptr);
    REQUIRE(log.has_error());
    CHECK(log.messages.back().second.find("token") != std::string::npos);

    fmi3Instance cs = co_simulation(log);
    REQUIRE(cs);
    log.messages.clear();
    bool event = false, stop = false, early = false;
    double last = 0.0;
    CHECK(FMI3(fmi3DoStep)(cs, 0.0, 0.01, true, &event, &stop, &early, &last) == fmi3Error);
    REQUIRE(log.has_error());
    CHECK(log.messages.back().second.find("DoStep is not allowed in Instantiated") !=
          std::string::npos);
    REQUIRE(FMI3(fmi3EnterInitializationMode)(cs, false, 0.0, 0.0, false, 0.0) == fmi3OK);
    CHECK(FMI3(fmi3DoStep)(cs, 0.0, 0.01, true, &event, &stop, &early, &last) == fmi3Error);
    REQUIRE(FMI3(fmi3ExitInitializationMode)(cs) == fmi3OK);
    // A fixed parameter after initialization; a communication point that is not the time.
    const fmi3ValueReference step[] = {vr::step};
    const double h = 0.1;
    CHECK(FMI3(fmi3SetFloat64)(cs, step, 1, &h, 1) == fmi3Error);
    CHECK(FMI3(fmi3DoStep)(cs, 0.5, 0.01, true, &event, &stop, &early, &last) == fmi3Error);
    CHECK(FMI3(fmi3DoStep)(cs, 0.0, 0.01, true, &event, &stop, &early, &last) == fmi3OK);
    // Model exchange's functions are not co-simulation's; the unit has no Float32.
    CHECK(FMI3(fmi3EnterContinuousTimeMode)(cs) == fmi3Error);
    const fmi3ValueReference t[] = {vr::time};
    float f = 0.0F;
    CHECK(FMI3(fmi3GetFloat32)(cs, t, 1, &f, 1) == fmi3Error);
    const fmi3ValueReference bad[] = {999};
    double value = 0.0;
    CHECK(FMI3(fmi3GetFloat64)(cs, bad, 1, &value, 1) == fmi3Error);
    CHECK(FMI3(fmi3Terminate)(cs) == fmi3OK);
    CHECK(FMI3(fmi3DoStep)(cs, 0.01, 0.01, true, &event, &stop, &early, &last) == fmi3Error);
    // Reset: back to Instantiated with the start values.
    CHECK(FMI3(fmi3Reset)(cs) == fmi3OK);
    initialize(cs);
    CHECK(get(cs, vr::time) == 0.0);
    CHECK(get(cs, vr::th1) == 0.5);
    FMI3(fmi3FreeInstance)(cs);

    fmi3Instance me = model_exchange(log);
    REQUIRE(me);
    double xdot[4];
    CHECK(FMI3(fmi3GetContinuousStateDerivatives)(me, xdot, 4) == fmi3Error);
    initialize(me);
    CHECK(FMI3(fmi3GetContinuousStateDerivatives)(me, xdot, 3) == fmi3Error); // the wrong count
    CHECK(FMI3(fmi3DoStep)(me, 0.0, 0.01, true, &event, &stop, &early, &last) == fmi3Error);
    FMI3(fmi3FreeInstance)(me);
    CHECK(FMI3(fmi3InstantiateScheduledExecution)("s", token, nullptr, false, false, &log, fmi3_log,
                                                  nullptr, nullptr, nullptr) == nullptr);
}

TEST_CASE("fmi3: a serialized state read back continues the run to the last bit; damaged bytes and "
          "ABM4's "
          "history are refused") {
    Log log;
    fmi3Instance in = started(log, {0.4, 0.1}, yamsc::runtime::Method::rk4);
    run(in, 0.01, 20);
    fmi3FMUState state = nullptr;
    REQUIRE(FMI3(fmi3GetFMUState)(in, &state) == fmi3OK);
    size_t size = 0;
    REQUIRE(FMI3(fmi3SerializedFMUStateSize)(in, state, &size) == fmi3OK);
    std::vector<fmi3Byte> bytes(size);
    REQUIRE(FMI3(fmi3SerializeFMUState)(in, state, bytes.data(), size) == fmi3OK);
    CHECK(FMI3(fmi3SerializeFMUState)(in, state, bytes.data(), size - 1) == fmi3Error);
    REQUIRE(FMI3(fmi3FreeFMUState)(in, &state) == fmi3OK);
    const auto first = run(in, 0.01, 10);

    // Into a second instance: it continues from the point the bytes hold.
    Log other_log;
    fmi3Instance other = started(other_log, {0.0, 0.0}, yamsc::runtime::Method::rk4);
    fmi3FMUState read = nullptr;
    REQUIRE(FMI3(fmi3DeserializeFMUState)(other, bytes.data(), size, &read) == fmi3OK);
    REQUIRE(FMI3(fmi3SetFMUState)(other, read) == fmi3OK);
    CHECK(get(other, vr::time) == doctest::Approx(0.2).epsilon(1e-14));
    CHECK(get(other, vr::tau) == 0.4);
    CHECK(run(other, 0.01, 10) == first);
    CHECK(FMI3(fmi3FreeFMUState)(other, &read) == fmi3OK);

    std::vector<fmi3Byte> cut(bytes.begin(), bytes.end() - 3), bad = bytes;
    bad[0] = 'x';
    CHECK(FMI3(fmi3DeserializeFMUState)(other, cut.data(), cut.size(), &read) == fmi3Error);
    CHECK(FMI3(fmi3DeserializeFMUState)(other, bad.data(), bad.size(), &read) == fmi3Error);
    CHECK(read == nullptr);
    CHECK(other_log.has_error());
    FMI3(fmi3FreeInstance)(other);

    // ABM4's history is not serialized: the state of an ABM4 run past its first step is refused.
    fmi3Instance abm = started(log, {0.4, 0.1}, yamsc::runtime::Method::abm4);
    run(abm, 0.01, 5);
    REQUIRE(FMI3(fmi3GetFMUState)(abm, &state) == fmi3OK);
    log.messages.clear();
    CHECK(FMI3(fmi3SerializedFMUStateSize)(abm, state, &size) == fmi3Error);
    REQUIRE(log.has_error());
    CHECK(log.messages.back().second.find("ABM4's history") != std::string::npos);
    FMI3(fmi3FreeFMUState)(abm, &state);
    FMI3(fmi3FreeInstance)(abm);
    FMI3(fmi3FreeInstance)(in);
}
