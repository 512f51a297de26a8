#pragma once
// One fixed-step integrator (RK4 or ABM4) behind one interface, for loops that
// drive the steps themselves (a controller in the loop changes the inputs
// between steps). simulate_rk4 / simulate_abm4 run the same steps.
#include "yamsc/abm4.hpp"
#include "yamsc/rk4.hpp"
#include "yamsc/simulation.hpp"

#include <cstddef>
#include <optional>

namespace yamsc::runtime {

class FixedStepper {
public:
    /// method: rk4 or abm4 (std::invalid_argument for cvode); n states.
    FixedStepper(Method method, OdeFunction f, std::size_t n);

    /// Advances x from t to t + dt in place; throws std::runtime_error, as
    /// simulate_rk4 does, when the state is no longer finite afterwards.
    void step(double t, double dt, double* x);

private:
    Method method_;
    OdeFunction f_;
    std::size_t n_;
    std::optional<Rk4Workspace> rk4_;
    std::optional<Abm4Integrator> abm4_;
};

} // namespace yamsc::runtime
