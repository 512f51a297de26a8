#include "yamsc/simulation.hpp"

#include "yamsc/abm4.hpp"
#include "yamsc/cvode.hpp"
#include "yamsc/rk4.hpp"

#include "fixed_step.hpp"

#include <cmath>
#include <stdexcept>

namespace yamsc::runtime {

std::optional<Method> parse_method(const std::string& name) {
    if (name == "rk4") return Method::rk4;
    if (name == "abm4") return Method::abm4;
    if (name == "cvode") return Method::cvode;
    return std::nullopt;
}

const char* method_name(Method method) {
    switch (method) {
    case Method::rk4:
        return "rk4";
    case Method::abm4:
        return "abm4";
    case Method::cvode:
        break;
    }
    return "cvode";
}

double SimulationResult::value(std::size_t row, std::size_t column) const {
    if (column == 0) return time[row];
    const std::size_t state_column = column - 1;
    if (state_column < static_cast<std::size_t>(nx)) return state_row(row)[state_column];
    return output_row(row)[state_column - static_cast<std::size_t>(nx)];
}

std::vector<std::string> column_names(const ModelView& view) {
    std::vector<std::string> names{"time"};
    for (int i = 0; i < view.nx(); ++i) names.push_back(state_name(view, i));
    for (int i = 0; i < view.ny; ++i)
        names.push_back(static_cast<std::size_t>(i) < view.output_names.size()
                            ? view.output_names[static_cast<std::size_t>(i)]
                            : "y" + std::to_string(i));
    return names;
}

namespace {

// Throttles progress reports to about one per percent of the run.
class ProgressReporter {
public:
    ProgressReporter(const ProgressCallback& callback, double t_start, double t_end)
        : callback_(callback), t_start_(t_start), t_end_(t_end),
          interval_((t_end - t_start) / 100.0), next_(t_start + interval_) {}

    bool report(double t) {
        if (!callback_) return true;
        if (t < next_ && t < t_end_) return true;
        while (next_ <= t) next_ += interval_ > 0.0 ? interval_ : t_end_ - t_start_ + 1.0;
        return callback_(t, t_end_);
    }

private:
    const ProgressCallback& callback_;
    double t_start_, t_end_, interval_, next_;
};

void check_view(const ModelView& view) {
    if (!view.rhs) throw std::invalid_argument("the model view has no right-hand side");
    if (view.ny > 0 && !view.outputs)
        throw std::invalid_argument("the model view declares outputs but cannot compute them");
}

} // namespace

std::size_t output_stride(double dt, double dt_out) {
    if (dt_out == 0.0) return 1;
    const double ratio = dt_out / dt;
    const double stride = std::round(ratio);
    if (!std::isfinite(ratio) || stride < 1.0 || std::abs(ratio - stride) > 1e-9 * stride)
        throw std::invalid_argument("the output step must be a multiple of the time step");
    return static_cast<std::size_t>(stride);
}

SimulationResult simulate(const ModelView& view, const SimulationOptions& options,
                          const ProgressCallback& progress) {
    check_view(view);
    check_initial_state(view, options.x0);
    if (!options.u_of_t) check_input_size(view, options.u);
    const TimeGrid grid(options.t_start, options.t_end, options.dt);
    const std::size_t stride = output_stride(options.dt, options.dt_out);
    const InputFunction inputs = options.u_of_t ? options.u_of_t : constant_input(options.u);

    SimulationResult result;
    result.columns = column_names(view);
    result.nx = view.nx();
    result.ny = view.ny;
    const std::size_t rows = (grid.size() - 1) / stride + 2;
    result.time.reserve(rows);
    result.states.reserve(rows * static_cast<std::size_t>(result.nx));
    result.outputs.reserve(rows * static_cast<std::size_t>(result.ny));

    const auto nq = static_cast<std::size_t>(view.nq);
    std::vector<double> u(static_cast<std::size_t>(view.nu));
    std::vector<double> y(static_cast<std::size_t>(view.ny));
    ProgressReporter reporter(progress, options.t_start, options.t_end);
    std::size_t step = 0; // of the grid, counted by the observer
    // Rows every `stride` steps and the last one: the outputs only where they
    // are stored. `derivative` gives x' at the point (the fixed-step
    // integrators', which their next step reuses; null for CVODE): with its q''
    // a row costs outputs_from_qdd, not outputs' own rhs, for the same numbers.
    const auto record = [&](double t, const double* x, detail::PointDerivative* derivative) {
        const bool store = step++ % stride == 0 || step == grid.size();
        if (!store) return result.completed = reporter.report(t);
        result.time.push_back(t);
        result.states.insert(result.states.end(), x, x + result.nx);
        if (view.ny > 0) {
            // x' first: it evaluates the inputs at t itself, as the next step would.
            const double* xdot = derivative && view.outputs_from_qdd ? (*derivative)() : nullptr;
            if (view.nu > 0) inputs(t, u.data());
            if (xdot)
                view.outputs_from_qdd(t, x, x + nq, xdot + nq, u.data(), y.data());
            else
                view.outputs(t, x, x + nq, u.data(), y.data());
            result.outputs.insert(result.outputs.end(), y.begin(), y.end());
        }
        result.completed = reporter.report(t);
        return result.completed;
    };
    const detail::DerivativeObserver fixed_step_record = [&](double t, const double* x,
                                                             detail::PointDerivative& derivative) {
        return record(t, x, &derivative);
    };

    // Without a state (a model whose motion is all prescribed, no block states)
    // there is nothing to integrate: every method evaluates the outputs on the
    // grid of dt, which the fixed-step loop walks (CVODE takes no empty system).
    if (options.method == Method::rk4 || result.nx == 0) {
        detail::simulate_rk4_observing(view, options.x0, inputs, options.t_end, options.dt,
                                       fixed_step_record, options.t_start);
    } else if (options.method == Method::abm4) {
        detail::simulate_abm4_observing(view, options.x0, inputs, options.t_end, options.dt,
                                        fixed_step_record, options.t_start);
    } else {
        CvodeOptions cvode;
        cvode.rtol = options.rtol;
        cvode.atol = options.atol;
        // CVODE's output points are interpolated: it has no rhs there. The
        // blocks' discrete states advance between output points.
        std::vector<double> x_last, u_last(u.size()), u_now(u.size());
        double t_last = options.t_start;
        simulate_cvode(
            view, options.x0, inputs, options.t_end, options.dt,
            [&](double t, const double* x) {
                if (view.update_discrete && !x_last.empty()) {
                    if (view.nu > 0) {
                        inputs(t_last, u_last.data());
                        inputs(t, u_now.data());
                    }
                    view.update_discrete(t_last, x_last.data(), u_last.data(), t, x, u_now.data());
                }
                x_last.assign(x, x + result.nx);
                t_last = t;
                return record(t, x, nullptr);
            },
            cvode, options.t_start);
    }
    return result;
}

} // namespace yamsc::runtime
