#pragma once
// What the Python module holds for a model: the loaded library (compiled
// through the JIT's cache, or built beforehand), its bound parameters and the
// view at other parameters a call asks for. No pybind11 here: the binding
// (module.cpp) converts arrays and exceptions.
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"

#include <yamsc/model_view.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace yamsc::python {

/// A model that cannot be loaded: the message is yamsc's, located
/// (file:line:col) for errors in the model file.
struct LoadError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The documentation of a named quantity: its doc comment and the unit written
/// in brackets at its end (`# link length [m]`), empty when there is none.
struct Described {
    std::string name, doc, unit;
};

class ModelHandle {
public:
    /// Checks and compiles a model file like `yamsc sim`: `routines` of the ABI
    /// (empty: every one) in one cached library, shared with the commands that
    /// compile the same routines. `external`: the model's external functions
    /// (a library or a C/C++ source, as `--external`). `blocks`: the load
    /// blocks the model declares that are closed around it, as `yamsc sim`
    /// closes them (analysis/load_blocks.hpp). Throws LoadError with the diagnostics.
    static ModelHandle from_source(const std::string& path, const std::string& sid,
                                   const std::vector<driver::Assignment>& set,
                                   std::vector<std::string> routines,
                                   const std::string& external = "",
                                   const analysis::BlockOptions& blocks = {});
    /// A library exporting a model (abi_export.hpp), bound to its defaults and `set`.
    static ModelHandle from_library(const std::string& path,
                                    const std::vector<driver::Assignment>& set);

    const analysis::Loaded& loaded() const { return loaded_; }
    const runtime::ModelView& view() const { return loaded_.view; }
    const runtime::SharedModel& library() const { return *loaded_.library; }
    int np() const { return library().np(); }

    /// The view bound to `p` (np values), or to the model's parameters when
    /// `p` is null. The last one is kept, so repeated calls with the same
    /// parameters bind nothing.
    const runtime::ModelView& view_at(const double* p);
    /// The parameters of view_at(p).
    std::vector<double> params_at(const double* p) const;

    /// DOFs, input channels, parameters and outputs with their documentation
    /// (kind: "dofs", "inputs", "params", "outputs"); a library has no docs.
    std::vector<Described> described(const std::string& kind) const;

private:
    analysis::Loaded loaded_;
    analysis::BlockOptions blocks_;
    std::vector<double> other_params_;
    runtime::ModelView other_view_;
};

} // namespace yamsc::python
