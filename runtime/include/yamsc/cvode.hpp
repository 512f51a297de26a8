#pragma once
// SUNDIALS CVODE (variable-order BDF, Newton iteration, dense direct linear
// solver) for stiff models such as flexible bodies with high-frequency modes.
// The model's exact Jacobian is used when the view has one.
#include "yamsc/integration.hpp"
#include "yamsc/model_view.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace yamsc::runtime {

struct CvodeOptions {
    double rtol = 1e-6;
    double atol = 1e-8;
    /// Internal steps allowed between two output times before giving up.
    long max_steps_per_output = 100000;
    /// Largest internal step; 0 lets CVODE choose.
    double max_step = 0.0;
    /// Use view.rhs_jacobian when present; otherwise (or when false) CVODE
    /// approximates the Jacobian by difference quotients.
    bool use_exact_jacobian = true;
};

/// Counters of a finished run, for reports and benchmarks.
struct CvodeStats {
    long steps = 0;
    long rhs_evals = 0;
    long jacobian_evals = 0;
    long error_test_failures = 0;
    long nonlinear_convergence_failures = 0;
    bool exact_jacobian = false;
};

/// A CVODE failure: the flag's name (e.g. CV_TOO_MUCH_WORK), CVODE's own message
/// and the time reached.
class CvodeError : public std::runtime_error {
public:
    CvodeError(int flag, const std::string& message) : std::runtime_error(message), flag_(flag) {}
    int flag() const { return flag_; }

private:
    int flag_;
};

/// Integrates the view from x0 at t_start to t_end, calling `observe` at each
/// output time (t_start, t_start + dt_out, ..., t_end; see TimeGrid). Throws
/// std::invalid_argument on bad arguments, CvodeError when CVODE fails, and
/// rethrows any exception raised by the model, the inputs or the observer.
CvodeStats simulate_cvode(const ModelView& view, const std::vector<double>& x0,
                          const InputFunction& u, double t_end, double dt_out,
                          const StateObserver& observe, const CvodeOptions& options = {},
                          double t_start = 0.0);
/// The same with constant inputs (nu values).
CvodeStats simulate_cvode(const ModelView& view, const std::vector<double>& x0,
                          const std::vector<double>& u, double t_end, double dt_out,
                          const StateObserver& observe, const CvodeOptions& options = {},
                          double t_start = 0.0);

} // namespace yamsc::runtime
