#include "yamsc/cvode.hpp"

#include "sundials_handles.hpp"

#include <cvode/cvode_ls.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <memory>
#include <sstream>

namespace yamsc::runtime {

namespace {

// State the C callbacks reach through CVODE's user-data pointer. Exceptions
// must not cross CVODE's C frames, so callbacks park them here and the driver
// loop rethrows them once CVode() has returned.
struct CallbackContext {
    const ModelView& view;
    const InputFunction& inputs;
    std::vector<double> u;
    std::vector<double> jacobian_row_major;
    std::exception_ptr error;
    std::string cvode_message;

    const double* inputs_at(double t) {
        if (view.nu > 0) inputs(t, u.data());
        return u.data();
    }
};

bool all_finite(const double* v, sunindextype n) {
    for (sunindextype i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

int rhs_callback(realtype t, N_Vector x, N_Vector xdot, void* user_data) {
    auto& ctx = *static_cast<CallbackContext*>(user_data);
    try {
        ctx.view.rhs(t, N_VGetArrayPointer(x), ctx.inputs_at(t), N_VGetArrayPointer(xdot));
    } catch (...) {
        ctx.error = std::current_exception();
        return -1; // unrecoverable: stop at once
    }
    // A positive value is a recoverable failure: CVODE retries with a smaller
    // step, which is the right reaction to a state that left the model's domain.
    return all_finite(N_VGetArrayPointer(xdot), N_VGetLength(xdot)) ? 0 : 1;
}

int jacobian_callback(realtype t, N_Vector x, N_Vector, SUNMatrix J, void* user_data, N_Vector,
                      N_Vector, N_Vector) {
    auto& ctx = *static_cast<CallbackContext*>(user_data);
    const auto n = static_cast<sunindextype>(ctx.view.nx());
    try {
        ctx.view.rhs_jacobian(t, N_VGetArrayPointer(x), ctx.inputs_at(t),
                              ctx.jacobian_row_major.data());
    } catch (...) {
        ctx.error = std::current_exception();
        return -1;
    }
    if (!all_finite(ctx.jacobian_row_major.data(), n * n)) return 1;
    // The model writes row-major; SUNDIALS dense matrices are column-major.
    for (sunindextype j = 0; j < n; ++j) {
        realtype* column = SUNDenseMatrix_Column(J, j);
        for (sunindextype i = 0; i < n; ++i)
            column[i] = ctx.jacobian_row_major[static_cast<std::size_t>(i * n + j)];
    }
    return 0;
}

// Keeps CVODE's message for the exception instead of letting it print to stderr.
void error_handler(int error_code, const char*, const char*, char* message, void* user_data) {
    if (error_code < 0) static_cast<CallbackContext*>(user_data)->cvode_message = message;
}

std::string flag_name(int flag, bool linear_solver) {
    // Both functions return a string allocated with malloc.
    std::unique_ptr<char, decltype(&std::free)> name(
        linear_solver ? CVodeGetLinReturnFlagName(flag) : CVodeGetReturnFlagName(flag), &std::free);
    return name ? std::string(name.get()) : "flag " + std::to_string(flag);
}

const char* hint_for(int flag) {
    switch (flag) {
    case CV_TOO_MUCH_WORK:
        return "; the model may be very stiff or its solution unbounded: loosen the tolerances or "
               "raise "
               "the step limit";
    case CV_TOO_MUCH_ACC:
        return "; the tolerances are tighter than double precision allows";
    case CV_ERR_FAILURE:
    case CV_CONV_FAILURE:
        return "; the model may be discontinuous, singular or unstable here";
    case CV_RHSFUNC_FAIL:
    case CV_FIRST_RHSFUNC_ERR:
    case CV_REPTD_RHSFUNC_ERR:
    case CV_UNREC_RHSFUNC_ERR:
        return "; the model's right-hand side is not finite (singular mass matrix?)";
    default:
        return "";
    }
}

// Throws the exception a callback parked, if any, else a CvodeError for a
// negative flag, with CVODE's own message and a hint.
void check(const CallbackContext& callbacks, int flag, const char* call, bool linear_solver = false,
           double t = std::numeric_limits<double>::quiet_NaN()) {
    if (callbacks.error) std::rethrow_exception(callbacks.error);
    if (flag >= 0) return;
    std::ostringstream msg;
    msg << "CVODE " << call << " failed";
    if (!std::isnan(t)) msg << " at t = " << t << " s";
    msg << " (" << flag_name(flag, linear_solver) << ")";
    std::string detail = callbacks.cvode_message;
    while (!detail.empty() && (detail.back() == '.' || detail.back() == ' ')) detail.pop_back();
    if (!detail.empty()) msg << ": " << detail;
    msg << hint_for(flag);
    throw CvodeError(flag, msg.str());
}

void check_options(const CvodeOptions& o) {
    if (!(o.rtol > 0.0) || !std::isfinite(o.rtol))
        throw std::invalid_argument("relative tolerance must be positive");
    if (!(o.atol > 0.0) || !std::isfinite(o.atol))
        throw std::invalid_argument("absolute tolerance must be positive");
    if (o.max_steps_per_output <= 0)
        throw std::invalid_argument("the step limit per output must be positive");
    if (!(o.max_step >= 0.0)) throw std::invalid_argument("maximum step must not be negative");
}

} // namespace

CvodeStats simulate_cvode(const ModelView& view, const std::vector<double>& x0,
                          const InputFunction& u, double t_end, double dt_out,
                          const StateObserver& observe, const CvodeOptions& options,
                          double t_start) {
    check_initial_state(view, x0);
    check_options(options);
    if (view.nq <= 0) throw std::invalid_argument("the model has no degrees of freedom");
    if (!view.rhs) throw std::invalid_argument("the model view has no right-hand side");
    if (view.nu > 0 && !u) throw std::invalid_argument("the model has inputs but none were given");
    const TimeGrid grid(t_start, t_end, dt_out);
    const auto n = static_cast<sunindextype>(view.nx());
    const bool exact_jacobian = options.use_exact_jacobian && static_cast<bool>(view.rhs_jacobian);

    CallbackContext callbacks{view,
                              u,
                              std::vector<double>(static_cast<std::size_t>(view.nu)),
                              std::vector<double>(exact_jacobian ? x0.size() * x0.size() : 0),
                              nullptr,
                              {}};

    // Declaration order is destruction order reversed: CVODE's memory goes
    // first, the context last.
    sundials::Context context;
    sundials::Vector x(sundials::checked(N_VNew_Serial(n, context), "the state vector"));
    std::copy(x0.begin(), x0.end(), N_VGetArrayPointer(x.get()));
    sundials::Matrix jacobian(sundials::checked(SUNDenseMatrix(n, n, context), "the Jacobian"));
    sundials::LinearSolver solver(
        sundials::checked(SUNLinSol_Dense(x.get(), jacobian.get(), context), "the linear solver"));
    sundials::CvodeMemory cvode(sundials::checked(CVodeCreate(CV_BDF, context), "CVODE"));
    void* mem = cvode.get();

    check(callbacks, CVodeSetErrHandlerFn(mem, error_handler, &callbacks), "CVodeSetErrHandlerFn");
    check(callbacks, CVodeInit(mem, rhs_callback, grid[0], x.get()), "CVodeInit");
    check(callbacks, CVodeSetUserData(mem, &callbacks), "CVodeSetUserData");
    check(callbacks, CVodeSStolerances(mem, options.rtol, options.atol), "CVodeSStolerances");
    check(callbacks, CVodeSetLinearSolver(mem, solver.get(), jacobian.get()),
          "CVodeSetLinearSolver", true);
    if (exact_jacobian)
        check(callbacks, CVodeSetJacFn(mem, jacobian_callback), "CVodeSetJacFn", true);
    check(callbacks, CVodeSetMaxNumSteps(mem, options.max_steps_per_output), "CVodeSetMaxNumSteps");
    if (options.max_step > 0.0)
        check(callbacks, CVodeSetMaxStep(mem, options.max_step), "CVodeSetMaxStep");
    // Never step past the end: inputs need not be defined beyond it.
    check(callbacks, CVodeSetStopTime(mem, grid[grid.size() - 1]), "CVodeSetStopTime");

    double* state = N_VGetArrayPointer(x.get());
    bool keep_going = !observe || observe(grid[0], state);
    for (std::size_t k = 1; k < grid.size() && keep_going; ++k) {
        realtype reached = grid[k - 1];
        const int flag = CVode(mem, grid[k], x.get(), &reached, CV_NORMAL);
        check(callbacks, flag, "step", false, reached);
        if (view.project) {
            // Back onto the constraints at each output point, and CVODE restarted
            // from there (its history belongs to the unprojected solution).
            view.project(grid[k], state, callbacks.inputs_at(grid[k]));
            check(callbacks, CVodeReInit(mem, grid[k], x.get()), "CVodeReInit");
        }
        keep_going = !observe || observe(grid[k], state);
    }

    CvodeStats stats;
    stats.exact_jacobian = exact_jacobian;
    CVodeGetNumSteps(mem, &stats.steps);
    CVodeGetNumRhsEvals(mem, &stats.rhs_evals);
    CVodeGetNumJacEvals(mem, &stats.jacobian_evals);
    CVodeGetNumErrTestFails(mem, &stats.error_test_failures);
    CVodeGetNumNonlinSolvConvFails(mem, &stats.nonlinear_convergence_failures);
    return stats;
}

CvodeStats simulate_cvode(const ModelView& view, const std::vector<double>& x0,
                          const std::vector<double>& u, double t_end, double dt_out,
                          const StateObserver& observe, const CvodeOptions& options,
                          double t_start) {
    check_input_size(view, u);
    return simulate_cvode(view, x0, constant_input(u), t_end, dt_out, observe, options, t_start);
}

} // namespace yamsc::runtime
