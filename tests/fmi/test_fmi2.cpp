// The FMI 2.0 functions of the same unit: the same core behind the 2.0 names
// (model exchange's derivatives, a co-simulation step, states, derivatives,
// the state machine, the resource URI).
#include "fmi_host.hpp"
#include "pendulum.hpp"

#include "yamsc/simulation.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace fmi_test;

namespace {

Log fmi2_messages;
const fmi2CallbackFunctions callbacks{fmi2_log, nullptr, nullptr, nullptr, &fmi2_messages};

fmi2Component instantiate(fmi2Type type, const char* guid = token) {
    return FMI2(fmi2Instantiate)("pendulum", type, guid, "file:///tmp/a%20b/resources", &callbacks,
                                 fmi2False, fmi2False);
}

void initialize(fmi2Component c) {
    REQUIRE(FMI2(fmi2SetupExperiment)(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) == fmi2OK);
    REQUIRE(FMI2(fmi2EnterInitializationMode)(c) == fmi2OK);
    REQUIRE(FMI2(fmi2ExitInitializationMode)(c) == fmi2OK);
}

} // namespace

TEST_CASE(
    "fmi2: the unit exports every function of the standard's model exchange and co-simulation") {
    for (const char* name : {"fmi2GetTypesPlatform",
                             "fmi2GetVersion",
                             "fmi2SetDebugLogging",
                             "fmi2Instantiate",
                             "fmi2FreeInstance",
                             "fmi2SetupExperiment",
                             "fmi2EnterInitializationMode",
                             "fmi2ExitInitializationMode",
                             "fmi2Terminate",
                             "fmi2Reset",
                             "fmi2GetReal",
                             "fmi2GetInteger",
                             "fmi2GetBoolean",
                             "fmi2GetString",
                             "fmi2SetReal",
                             "fmi2SetInteger",
                             "fmi2SetBoolean",
                             "fmi2SetString",
                             "fmi2GetFMUstate",
                             "fmi2SetFMUstate",
                             "fmi2FreeFMUstate",
                             "fmi2SerializedFMUstateSize",
                             "fmi2SerializeFMUstate",
                             "fmi2DeSerializeFMUstate",
                             "fmi2GetDirectionalDerivative",
                             "fmi2EnterEventMode",
                             "fmi2NewDiscreteStates",
                             "fmi2EnterContinuousTimeMode",
                             "fmi2CompletedIntegratorStep",
                             "fmi2SetTime",
                             "fmi2SetContinuousStates",
                             "fmi2GetDerivatives",
                             "fmi2GetEventIndicators",
                             "fmi2GetContinuousStates",
                             "fmi2GetNominalsOfContinuousStates",
                             "fmi2SetRealInputDerivatives",
                             "fmi2GetRealOutputDerivatives",
                             "fmi2DoStep",
                             "fmi2CancelStep",
                             "fmi2GetStatus",
                             "fmi2GetRealStatus",
                             "fmi2GetIntegerStatus",
                             "fmi2GetBooleanStatus",
                             "fmi2GetStringStatus"}) {
        INFO(name);
        CHECK(unit().symbol(name) != nullptr);
    }
    CHECK(std::string(FMI2(fmi2GetVersion)()) == "2.0");
    CHECK(std::string(FMI2(fmi2GetTypesPlatform)()) == "default");
}

TEST_CASE("fmi2: model exchange's derivatives are the view's rhs, its directional derivatives the "
          "exact Jacobian") {
    fmi2Component c = instantiate(fmi2ModelExchange);
    REQUIRE(c);
    initialize(c);
    fmi2EventInfo info{fmi2True, fmi2True, fmi2True, fmi2True, fmi2True, 1.0};
    CHECK(FMI2(fmi2NewDiscreteStates)(c, &info) == fmi2OK);
    CHECK(info.newDiscreteStatesNeeded == fmi2False);
    CHECK(info.nextEventTimeDefined == fmi2False);
    REQUIRE(FMI2(fmi2EnterContinuousTimeMode)(c) == fmi2OK);
    const std::vector<double> x{-0.2, 1.4, 0.3, -2.0}, u{-0.5, 0.8};
    const fmi2ValueReference inputs[] = {vr::tau, vr::f};
    REQUIRE(FMI2(fmi2SetTime)(c, 1.5) == fmi2OK);
    REQUIRE(FMI2(fmi2SetContinuousStates)(c, x.data(), 4) == fmi2OK);
    REQUIRE(FMI2(fmi2SetReal)(c, inputs, 2, u.data()) == fmi2OK);
    std::vector<double> xdot(4), ref(4);
    REQUIRE(FMI2(fmi2GetDerivatives)(c, xdot.data(), 4) == fmi2OK);
    const auto view = pendulum();
    view.rhs(1.5, x.data(), u.data(), ref.data());
    for (int i = 0; i < 4; ++i)
        CHECK(std::abs(xdot[i] - ref[i]) <= 1e-15 * (1.0 + std::abs(ref[i])));

    std::vector<double> A(16);
    view.rhs_jacobian(1.5, x.data(), u.data(), A.data());
    const fmi2ValueReference unknowns[] = {vr::th1d, vr::th2d, vr::th1dd, vr::th2dd};
    const fmi2ValueReference knowns[] = {vr::th1, vr::th2, vr::th1d, vr::th2d};
    for (int j = 0; j < 4; ++j) {
        double seed[4] = {0, 0, 0, 0}, s[4];
        seed[j] = 1.0;
        REQUIRE(FMI2(fmi2GetDirectionalDerivative)(c, unknowns, 4, knowns, 4, seed, s) == fmi2OK);
        for (int i = 0; i < 4; ++i) CHECK(s[i] == A[i * 4 + j]);
    }
    fmi2Boolean event = fmi2True, stop = fmi2True;
    CHECK(FMI2(fmi2CompletedIntegratorStep)(c, fmi2True, &event, &stop) == fmi2OK);
    CHECK(event == fmi2False);
    FMI2(fmi2FreeInstance)(c);
}

TEST_CASE("fmi2: a co-simulation step is runtime::simulate's RK4 step; states round-trip") {
    fmi2Component c = instantiate(fmi2CoSimulation);
    REQUIRE(c);
    const fmi2ValueReference inputs[] = {vr::tau, vr::f};
    const std::vector<double> u{0.2, 0.6};
    REQUIRE(FMI2(fmi2SetReal)(c, inputs, 2, u.data()) == fmi2OK);
    initialize(c);
    yamsc::runtime::SimulationOptions o;
    o.t_end = 0.5;
    o.dt = 0.01;
    o.x0 = x_start;
    o.u = u;
    const auto ref = yamsc::runtime::simulate(pendulum(), o);
    const fmi2ValueReference vrs[] = {vr::th1, vr::th2, vr::th1d, vr::th2d, vr::z_tip};
    double worst = 0.0, t = 0.0;
    fmi2FMUstate state = nullptr;
    std::vector<double> at_half(5);
    for (int k = 1; k <= 50; ++k) {
        REQUIRE(FMI2(fmi2DoStep)(c, t, 0.01, fmi2True) == fmi2OK);
        t += 0.01;
        double v[5];
        REQUIRE(FMI2(fmi2GetReal)(c, vrs, 5, v) == fmi2OK);
        for (int i = 0; i < 4; ++i) worst = std::max(worst, std::abs(v[i] - ref.state_row(k)[i]));
        worst = std::max(worst, std::abs(v[4] - ref.output_row(k)[1]));
        if (k == 25) {
            REQUIRE(FMI2(fmi2GetFMUstate)(c, &state) == fmi2OK);
            at_half.assign(v, v + 5);
        }
    }
    CHECK(worst <= 1e-12);
    double last = 0.0;
    CHECK(FMI2(fmi2GetRealStatus)(c, fmi2LastSuccessfulTime, &last) == fmi2OK);
    CHECK(last == doctest::Approx(0.5).epsilon(1e-14));
    REQUIRE(FMI2(fmi2SetFMUstate)(c, state) == fmi2OK);
    double v[5];
    REQUIRE(FMI2(fmi2GetReal)(c, vrs, 5, v) == fmi2OK);
    CHECK(std::vector<double>(v, v + 5) == at_half);
    // The same state through bytes.
    size_t size = 0;
    REQUIRE(FMI2(fmi2SerializedFMUstateSize)(c, state, &size) == fmi2OK);
    std::vector<fmi2Byte> bytes(size);
    REQUIRE(FMI2(fmi2SerializeFMUstate)(c, state, bytes.data(), size) == fmi2OK);
    CHECK(FMI2(fmi2FreeFMUstate)(c, &state) == fmi2OK);
    REQUIRE(FMI2(fmi2DoStep)(c, 0.25, 0.01, fmi2True) == fmi2OK);
    REQUIRE(FMI2(fmi2DeSerializeFMUstate)(c, bytes.data(), size, &state) == fmi2OK);
    REQUIRE(FMI2(fmi2SetFMUstate)(c, state) == fmi2OK);
    REQUIRE(FMI2(fmi2GetReal)(c, vrs, 5, v) == fmi2OK);
    CHECK(std::vector<double>(v, v + 5) == at_half);
    CHECK(FMI2(fmi2FreeFMUstate)(c, &state) == fmi2OK);
    FMI2(fmi2FreeInstance)(c);
}

TEST_CASE("fmi2: the state machine and the instantiation refuse what the standard does not allow") {
    fmi2_messages.messages.clear();
    CHECK(instantiate(fmi2CoSimulation, "{another-build}") == nullptr);
    CHECK(fmi2_messages.has_error());
    CHECK(FMI2(fmi2Instantiate)("p", fmi2CoSimulation, token, "http://host/resources", &callbacks,
                                fmi2False, fmi2False) == nullptr);
    fmi2Component c = instantiate(fmi2CoSimulation);
    REQUIRE(c);
    fmi2_messages.messages.clear();
    CHECK(FMI2(fmi2DoStep)(c, 0.0, 0.01, fmi2True) == fmi2Error);
    REQUIRE(fmi2_messages.has_error());
    CHECK(fmi2_messages.messages.back().second.find("not allowed in Instantiated") !=
          std::string::npos);
    initialize(c);
    CHECK(FMI2(fmi2SetupExperiment)(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) == fmi2Error);
    CHECK(FMI2(fmi2CancelStep)(c) == fmi2Error);
    const fmi2ValueReference m[] = {vr::method};
    const fmi2Integer cvode = 2;
    CHECK(FMI2(fmi2SetInteger)(c, m, 1, &cvode) == fmi2Error); // fixed after initialization
    FMI2(fmi2FreeInstance)(c);
}
