#pragma once
// What a unit's binary knows of its model. The glue source `yamsc fmu` writes
// is two lines,
//     #include "model.hpp"
//     #include <yamsc/fmi/unit.hpp>
//     YAMSC_FMI_UNIT(<namespace>::Model)
// (or YAMSC_FMI_UNIT_WITH(<namespace>::Model, settings) with the unit's
// settings); the macro defines unit_model(), which every FMI entry point of
// libyamsc_fmi.a reads (docs/fmi.md).
#include "yamsc/constraints.hpp"
#include "yamsc/fmi/fmi2_api.h"
#include "yamsc/fmi/fmi3_api.h"
#include "yamsc/fmi/variables.hpp"
#include "yamsc/model_view.hpp"
#include "yamsc/simulation.hpp"

#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace yamsc::fmi {

/// Closes the model's load blocks around its view: `base` is the model with
/// the parameters `params` bound, `resources` the unit's resources folder (a
/// native path ending with a separator). Returns the closed view
/// (runtime::close_blocks). Throws std::exception with a message the unit logs
/// when a block cannot be made (a missing or malformed data file).
using BlockHook =
    std::function<runtime::ModelView(const runtime::ModelView& base, const std::string& resources,
                                     const std::vector<double>& params)>;

/// What `yamsc fmu` decides for a unit, compiled into it.
struct UnitSettings {
    /// The instantiation token (FMI 3.0) or GUID (FMI 2.0) of the model
    /// description; an instantiation with another one is refused. Empty: not checked.
    std::string token;
    /// The co-simulation integrator and internal step (the start values of
    /// yamsc.method and yamsc.step).
    runtime::Method method = runtime::Method::rk4;
    double step = 1e-3;
    /// Start values of [q, q'] (2 nq), empty: zeros.
    std::vector<double> initial_state;
    /// Empty: the model has no load blocks.
    BlockHook close_blocks;
    /// Start values of the parameters (np, the model's order; `yamsc fmu --set`
    /// applied), empty: the model's defaults (Params{}).
    std::vector<double> parameters;
};
/// UnitSettings has `parameters` (glue written for older units tests it).
#define YAMSC_FMI_SETTINGS_HAVE_PARAMETERS 1

struct UnitModel {
    std::string name;
    std::vector<std::string> dof_names, input_names, output_names, param_names;
    std::vector<double> param_defaults; // np
    /// The model's view with its parameters (np values) bound.
    std::function<runtime::ModelView(const double* params)> make_view;
    /// The exact C (ny x 2 nq) and D (ny x nu) of the model's own outputs at
    /// (q, q', u): dy = C dx + D du. Empty when the model was compiled without them.
    std::function<void(const double* params, const double* q, const double* qd, const double* u,
                       double* C, double* D)>
        output_matrices;
    UnitSettings settings;
};

/// The unit's model: defined by YAMSC_FMI_UNIT in the unit's glue source.
__attribute__((visibility("hidden"))) const UnitModel& unit_model();

/// The layout of a unit's variables for the view it runs (load blocks closed)
/// with the parameters `params`: the unit's table is variables() of it.
UnitLayout unit_layout(const UnitModel& unit, const runtime::ModelView& view,
                       const std::vector<double>& params);

namespace detail {
template <class Model, class = void> struct has_output_matrices : std::false_type {};
template <class Model>
struct has_output_matrices<Model, std::void_t<decltype(&Model::output_matrices)>> : std::true_type {
};
} // namespace detail

/// The UnitModel of a generated C++ model (`<namespace>::Model`).
template <class Model> UnitModel make_unit_model(UnitSettings settings) {
    UnitModel u;
    u.name = Model::model_name;
    for (int i = 0; i < Model::nq; ++i) u.dof_names.emplace_back(Model::dof_names[i]);
    for (int i = 0; i < Model::nu; ++i) u.input_names.emplace_back(Model::input_names[i]);
    for (int i = 0; i < Model::ny; ++i) u.output_names.emplace_back(Model::output_names[i]);
    for (int i = 0; i < Model::np; ++i) u.param_names.emplace_back(Model::param_names[i]);
    u.param_defaults.assign(static_cast<std::size_t>(Model::np), 0.0);
    if constexpr (Model::np > 0)
        Model::params_to_array(typename Model::Params{}, u.param_defaults.data());
    // A model with constraint rows runs as `yamsc sim` runs it: constrained
    // (the KKT accelerations, projection after each step, the reactions as outputs).
    u.make_view = [](const double* params) {
        runtime::ModelView v;
        if constexpr (Model::np > 0)
            v = runtime::from_generated<Model>(Model::params_from_array(params));
        else
            v = runtime::from_generated<Model>(typename Model::Params{});
        return v.nc > 0 ? runtime::constrain(v) : v;
    };
    if constexpr (detail::has_output_matrices<Model>::value)
        u.output_matrices = [](const double* params, const double* q, const double* qd,
                               const double* u_in, double* C, double* D) {
            if constexpr (Model::np > 0)
                Model::output_matrices(q, qd, u_in, Model::params_from_array(params), C, D);
            else
                Model::output_matrices(q, qd, u_in, typename Model::Params{}, C, D);
        };
    if (!settings.parameters.empty()) {
        if (settings.parameters.size() != u.param_defaults.size())
            throw std::invalid_argument("the unit's settings give " +
                                        std::to_string(settings.parameters.size()) +
                                        " parameters, the model has " + std::to_string(Model::np));
        u.param_defaults = settings.parameters;
    }
    u.settings = std::move(settings);
    return u;
}

} // namespace yamsc::fmi

/// Defines the unit's model (one use per unit, at namespace scope). It also
/// refers to both C layers, so that linking libyamsc_fmi.a into the unit pulls
/// in every entry point without --whole-archive.
#define YAMSC_FMI_UNIT(Model) YAMSC_FMI_UNIT_WITH(Model, ::yamsc::fmi::UnitSettings{})
/// The same with the unit's settings (a yamsc::fmi::UnitSettings expression).
#define YAMSC_FMI_UNIT_WITH(Model, ...)                                                            \
    const ::yamsc::fmi::UnitModel& ::yamsc::fmi::unit_model() {                                    \
        static const ::yamsc::fmi::UnitModel unit =                                                \
            ::yamsc::fmi::make_unit_model<Model>(__VA_ARGS__);                                     \
        return unit;                                                                               \
    }                                                                                              \
    __attribute__((used)) static const char* (*const yamsc_fmi_entry_points[])(void) = {           \
        &fmi3GetVersion, &fmi2GetVersion};
