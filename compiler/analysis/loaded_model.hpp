#pragma once
// A model ready to run for `sim`, `lin` and `trim`: checked, compiled (only
// the routines the command calls, analysis/jit.hpp), bound to its parameters;
// and the points it starts from (`initial` and `linearize` blocks, --ic, --at).
#include "analysis/jit.hpp"
#include "codegen/routines.hpp"
#include "driver/commands.hpp"
#include "driver/outputs.hpp"
#include "driver/pipeline.hpp"

#include <yamsc/dynamic_model.hpp>

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::analysis {

/// A model compiled and bound to its parameters, ready to run. Copies share
/// the library (read-only), so `yamsc batch` loads a model once and binds
/// each case's parameters in a copy per thread.
struct Loaded {
    std::shared_ptr<const runtime::SharedModel> library;
    runtime::ModelView view;
    std::vector<double> params;
    driver::FrontEnd front; // the checked model (its equations are derived only to compile it);
                            // no model for a library loaded by load_library
    std::vector<driver::Assignment> sid_values; // from --sid, bound before --set
    std::string digest;                         // content_digest of the model text and data
};

/// `outputs` are checked against the model's data files before anything is derived.
/// `routines`: those the command calls (jit.hpp); a cached library of the same
/// model and routines is loaded without deriving the equations. nullopt when the
/// model has errors (already printed to `err`).
/// `external`: the implementation of the model's external functions (--external
/// lib.so|file.c|file.cpp, analysis/external_library.hpp); required when it declares any.
/// `channels`: ModelChannels::scene adds the scene's outputs (model/scene_channels.hpp)
/// after the model's own and every load block's.
std::optional<Loaded> load(const std::string& path, const std::vector<driver::Assignment>& set,
                           const std::string& sid_spec, bool verbose, std::ostream& err,
                           const std::vector<driver::NamedFile>& outputs,
                           codegen::RoutineSet routines, const std::string& external = "",
                           ModelChannels channels = ModelChannels::declared);

/// `load` without binding the parameters (`params` and `view` empty): for
/// commands that bind them per case with bind_parameters.
std::optional<Loaded> load_unbound(const std::string& path, const std::string& sid_spec,
                                   bool verbose, std::ostream& err,
                                   const std::vector<driver::NamedFile>& outputs,
                                   codegen::RoutineSet routines, const std::string& external = "",
                                   ModelChannels channels = ModelChannels::declared);

/// Binds the parameters again: the model's defaults, the --sid values, then
/// `set` (as `load` does); a view of the same library with those values.
void bind_parameters(Loaded& l, const std::vector<driver::Assignment>& set);

/// A model library built beforehand (abi_export.hpp's YAMSC_EXPORT_MODEL, e.g.
/// by CMake) bound to its defaults and `set`. It has no front end: no `initial`
/// or `linearize` block, so both points are zeros unless given.
Loaded load_library(const std::string& path, const std::vector<driver::Assignment>& set);

/// The routines `lin` and `trim` call: the second-order model and A.
codegen::RoutineSet linear_model_routines();

/// For `lin` and `trim`, which have nothing to do on a model without DOFs (its
/// motion all prescribed): true and the error, located at its `model` statement,
/// printed to `err`; false when the model has DOFs.
bool refuse_without_dofs(const Loaded& l, const std::string& command, const std::string& verb,
                         std::ostream& err);

/// Constant inputs from --u (0 where not given).
std::vector<double> inputs_of(const runtime::ModelView& v,
                              const std::vector<driver::Assignment>& u);

/// The model's `linearize` point evaluated at `params`, then overridden by
/// `at` (DOFs, rates, input channels) and `u` (inputs).
void operating_point(const Loaded& l, const std::vector<double>& params,
                     const std::vector<driver::Assignment>& at,
                     const std::vector<driver::Assignment>& u_given, std::vector<double>& q,
                     std::vector<double>& qd, std::vector<double>& u);

/// The model's `initial` block at the bound parameters (zeros without one), then --ic.
void initial_state(const Loaded& l, const std::vector<driver::Assignment>& ic,
                   std::vector<double>& q, std::vector<double>& qd);

} // namespace yamsc::analysis
