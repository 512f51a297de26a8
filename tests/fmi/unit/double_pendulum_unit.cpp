// The glue of a test unit, as `yamsc fmu` writes it: the generated double
// pendulum with its settings (a token, RK4 at 0.01 s, a start away from rest,
// the elbow damping c changed from the model's 0.1).
#include "double_pendulum.hpp"

#include <yamsc/fmi/unit.hpp>

namespace {

yamsc::fmi::UnitSettings settings() {
    yamsc::fmi::UnitSettings s;
    s.token = "{yamsc-test-double-pendulum}";
    s.method = yamsc::runtime::Method::rk4;
    s.step = 0.01;
    s.initial_state = {0.5, -0.3, 0.1, 0.2};
    s.parameters = {2.0, 1.0, 1.0, 0.8, 9.81, 5.0, 0.15};
    return s;
}

} // namespace

YAMSC_FMI_UNIT_WITH(double_pendulum::Model, settings())
