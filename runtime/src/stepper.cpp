#include "yamsc/stepper.hpp"

#include "fixed_step.hpp"

#include <stdexcept>
#include <utility>

namespace yamsc::runtime {

FixedStepper::FixedStepper(Method method, OdeFunction f, std::size_t n)
    : method_(method), f_(std::move(f)), n_(n) {
    if (method == Method::rk4)
        rk4_.emplace(n);
    else if (method == Method::abm4)
        abm4_.emplace(f_, n);
    else
        throw std::invalid_argument("a fixed-step loop runs rk4 or abm4, not " +
                                    std::string(method_name(method)));
}

void FixedStepper::step(double t, double dt, double* x) {
    if (rk4_)
        rk4_step(f_, t, dt, x, *rk4_);
    else
        abm4_->step(t, dt, x);
    for (std::size_t i = 0; i < n_; ++i)
        if (!std::isfinite(x[i]))
            detail::throw_diverged(method_ == Method::rk4 ? "RK4" : "ABM4", t + dt, dt);
}

} // namespace yamsc::runtime
