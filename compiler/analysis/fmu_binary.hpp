#pragma once
// A unit's binary (docs/packaging.md, "FMI units"): the model's generated C++
// and its header, a glue source that instantiates the FMI unit's runtime for
// the model (<yamsc/fmi/unit.hpp>), and the user's external functions, all
// compiled by the one compiler invocation (compiler_invocation.hpp) into a
// shared library that links the unit's runtime statically and exports only
// the FMI entry points.
#include "codegen/emit.hpp"

#include <yamsc/simulation.hpp>

#include <functional>
#include <string>
#include <vector>

namespace yamsc::analysis {

/// What the glue gives the unit besides the model's code: the values a host
/// finds as start values in modelDescription.xml, which the unit must use when
/// the host sets none.
struct UnitSettings {
    std::string model_namespace;                   // of the generated Model
    std::string token;                             // FMI 3.0 instantiationToken, FMI 2.0 guid
    std::vector<double> parameters;                // every parameter's start value (--set applied)
    std::vector<double> q0, qd0;                   // the states' start values (the `initial` block)
    runtime::Method method = runtime::Method::rk4; // the co-simulation step's integrator
    double step = 1e-3;
    /// Statements that set `s.close_blocks` (fmu_blocks.hpp), "" without blocks.
    std::string blocks; // its fixed step [s]
};

/// A file's bytes (UserError naming it when it cannot be read).
std::string file_bytes(const std::string& path);

/// The glue source (it includes the model's header as "model.hpp").
std::string glue_source(const UnitSettings& s);

struct UnitSources {
    codegen::EmittedFiles model; // its header written as model.hpp
    std::string glue;
    std::string external;            // the user's C or C++ source (a path), or ""
    std::string external_prototypes; // what it is compiled against
    bool blade_elements = false;     // links the AeroDyn reader (yamsc/fmi/blade_elements.hpp)
};

/// Compiles the unit into the bytes of its shared library. `compiler`: as the
/// JIT chooses it (jit_cache.hpp's compiler_of). Throws diag::UserError with the
/// compiler's messages when a source does not compile or the link fails.
std::string build_unit_binary(const UnitSources& sources, const std::string& compiler,
                              const std::function<void(const std::string&)>& progress);

} // namespace yamsc::analysis
