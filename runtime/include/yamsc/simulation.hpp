#pragma once
// The simulation driver: a model view plus options in, a table of time, states
// and outputs out. This is what `yamsc sim` runs and what a few lines of user
// code need to turn a generated model into a simulator.
#include "yamsc/integration.hpp"
#include "yamsc/model_view.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::runtime {

enum class Method { rk4, abm4, cvode };

/// "rk4", "abm4" or "cvode"; nullopt for anything else.
std::optional<Method> parse_method(const std::string& name);
const char* method_name(Method method);

struct SimulationOptions {
    double t_start = 0.0;
    double t_end = 1.0;
    /// RK4, ABM4: the step; CVODE: the output step (its internal steps are adaptive).
    double dt = 1e-3;
    /// The time between stored rows, a multiple of dt; 0: every step. Outputs
    /// are computed for the stored rows only (and always for the last one).
    double dt_out = 0.0;
    Method method = Method::rk4;
    /// CVODE tolerances.
    double rtol = 1e-6;
    double atol = 1e-8;
    /// Initial state [q, q'] (2 nq values).
    std::vector<double> x0;
    /// Constant inputs (nu values), used unless `u_of_t` is set.
    std::vector<double> u;
    /// Time-varying inputs; overrides `u` when set.
    InputFunction u_of_t;
};

/// Rows of the run: time, states and outputs at each output time. Column j of
/// the full table (time, states, outputs) is named columns[j].
struct SimulationResult {
    std::vector<std::string> columns;
    int nx = 0, ny = 0;
    std::vector<double> time;
    std::vector<double> states;  ///< row-major, rows() x nx
    std::vector<double> outputs; ///< row-major, rows() x ny
    /// False when the progress callback stopped the run early.
    bool completed = true;

    std::size_t rows() const { return time.size(); }
    std::size_t column_count() const { return columns.size(); }
    const double* state_row(std::size_t row) const { return states.data() + row * nx; }
    const double* output_row(std::size_t row) const { return outputs.data() + row * ny; }
    /// The value in the full table (column 0 is time).
    double value(std::size_t row, std::size_t column) const;
};

/// The CSV header of a view: time, <dof>..., <dof>'..., <output>... (cli.md).
std::vector<std::string> column_names(const ModelView& view);

/// Called with the time reached and the end time, about every 1 % of the run
/// and at its end; return false to stop early (the result is then marked
/// incomplete).
using ProgressCallback = std::function<bool(double t, double t_end)>;

/// The number of steps between stored rows for dt_out (1 for dt_out = 0).
/// Throws std::invalid_argument unless dt_out is 0 or a multiple of dt.
std::size_t output_stride(double dt, double dt_out);

/// Runs the simulation. Throws std::invalid_argument for inconsistent options
/// (sizes, steps, tolerances) and std::runtime_error (or CvodeError) when the
/// integration fails.
SimulationResult simulate(const ModelView& view, const SimulationOptions& options,
                          const ProgressCallback& progress = {});

} // namespace yamsc::runtime
