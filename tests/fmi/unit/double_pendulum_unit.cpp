// The glue of a test unit, as `yamsc fmu` writes it: the generated double
// pendulum with its settings (a token, RK4 at 0.01 s, a start away from rest).
#include "double_pendulum.hpp"

#include <yamsc/fmi/unit.hpp>

YAMSC_FMI_UNIT_WITH(double_pendulum::Model, yamsc::fmi::UnitSettings{"{yamsc-test-double-pendulum}",
                                                                     yamsc::runtime::Method::rk4,
                                                                     0.01,
                                                                     {0.5, -0.3, 0.1, 0.2},
                                                                     {}})
