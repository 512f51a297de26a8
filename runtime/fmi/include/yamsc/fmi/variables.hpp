#pragma once
// The value-reference table of a unit: every variable the unit exposes, with
// the attributes its model description declares. The unit dispatches get and
// set by it and `yamsc fmu` writes modelDescription.xml from it, so the two
// cannot disagree (docs/fmi.md, Variables).
//
// Order (value references are positions in this order):
//   0                time (independent)
//   states           q (nq), q' (nq), the load blocks' states z (nz)
//   second rates     q'' (nq), z' (nz)
//   inputs u (nu), parameters p (np), outputs y (ny)
//   the co-simulation settings: yamsc.method, yamsc.step
// The state derivatives are q' (the derivative of q), q'' (of q') and z' (of z):
// the state vector of model exchange is x = [q, q', z], the runtime's.
#include "yamsc/model_view.hpp"
#include "yamsc/simulation.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::fmi {

enum class Causality { independent, parameter, input, output, local };
enum class Variability { constant, fixed, tunable, discrete, continuous };
/// `none`: the attribute is not written (independent variables and inputs).
enum class Initial { none, exact, approx, calculated };
/// float64: Float64 (FMI 3.0) / Real (FMI 2.0); int32: Int32 / Integer.
enum class ValueType { float64, int32 };

/// What a variable is, for the unit's dispatch: which number of the instance it reads.
enum class Role {
    time,
    position,     // q[index]
    rate,         // q'[index]
    block_state,  // z[index]
    acceleration, // q''[index]
    block_rate,   // z'[index]
    input,        // u[index]
    parameter,    // p[index]
    output,       // y[index]
    method,       // the co-simulation integrator (runtime::Method as 0 rk4, 1 abm4, 2 cvode)
    step,         // the co-simulation internal step [s]
};

struct Variable {
    std::string name;
    std::uint32_t value_reference = 0;
    ValueType type = ValueType::float64;
    Causality causality = Causality::local;
    Variability variability = Variability::continuous;
    Initial initial = Initial::none;
    /// The start value (written where `initial` is exact or approx, and for inputs).
    double start = 0.0;
    /// The value reference of the variable this one is the time derivative of.
    std::optional<std::uint32_t> derivative_of;
    std::string description;
    Role role = Role::time;
    int index = 0; // within its role
};

/// What the table is made of: the sizes and names of the model as the unit
/// runs it (load blocks closed: their states and outputs included), its
/// parameters and the start values of the states and the settings.
struct UnitLayout {
    std::vector<std::string> dof_names;         // nq
    std::vector<std::string> block_state_names; // nz
    std::vector<std::string> input_names;       // nu
    std::vector<std::string> param_names;       // np
    std::vector<std::string> output_names;      // ny (the blocks' outputs after the model's)
    std::vector<double> initial_state;          // [q, q', z]: 2 nq + nz values
    std::vector<double> param_values;           // np start values
    /// Per parameter: whether it may change after initialization (tunable) or
    /// not (fixed). Empty: every parameter is tunable.
    std::vector<bool> param_tunable;
    /// Optional descriptions per variable name (empty or shorter: none).
    std::vector<std::string> dof_docs, input_docs, param_docs, output_docs;
    runtime::Method method = runtime::Method::rk4;
    double step = 1e-3;
};

/// The layout of a view (sizes, names, the blocks' states and initial values)
/// with the given parameters; states start at 0 (q, q') and at the blocks'
/// initial values (z). Settings and docs are the caller's to fill.
UnitLayout layout_of(const runtime::ModelView& view, std::vector<std::string> param_names,
                     std::vector<double> param_values);

/// THE value-reference table: variables[k].value_reference == k.
std::vector<Variable> variables(const UnitLayout& layout);

/// The value of yamsc.method for a runtime method, and back (nullopt: no method).
std::int32_t method_code(runtime::Method method);
std::optional<runtime::Method> method_of_code(std::int32_t code);

} // namespace yamsc::fmi
