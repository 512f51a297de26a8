#pragma once
// Models compiled on the fly: `yamsc sim` and `yamsc lin` run the model's
// generated C++ (not an interpreter). Only the routines the command calls are
// generated and compiled (sim: rhs and outputs), into a shared library loaded
// through the C ABI of runtime/include/yamsc/abi_export.hpp. Libraries are
// cached by content (jit_cache.hpp): a hit loads the library without deriving
// anything.
#include "codegen/routines.hpp"
#include "ir/system.hpp"

#include <yamsc/dynamic_model.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace yamsc::analysis {

struct JitOptions {
    std::string compiler;  // empty: jit_cache.hpp's compiler_of
    std::string cache_dir; // empty: jit_cache.hpp's cache_folder
    /// Details (which library is used), for --verbose.
    std::function<void(const std::string&)> progress;
    /// What is compiled and how long it usually takes: shown to the user
    /// whenever a compile starts, since it can take seconds.
    std::function<void(const std::string&)> notice;
};

/// What the generated code of a compiled model depends on.
/// The outputs compiled beside the model's own: none, or the scene's
/// (model/scene_channels.hpp, for `sim --vtk`). Part of the cache key.
enum class ModelChannels { declared, scene };

struct ModelIdentity {
    std::string model_name;
    std::string content_digest; // driver::content_digest: model text and data
    /// Routines of the C ABI (codegen::abi_routines(): rhs, rhs_jacobian,
    /// mass_matrix, forcing, jacobians, outputs). rhs is always compiled.
    codegen::RoutineSet routines;
    ModelChannels channels = ModelChannels::declared;
};

/// The C++ translation unit that exports `routines` of a model: the generated
/// source with those routines only, and the ABI shim for each.
std::string shared_model_source(const ir::System& eq, codegen::RoutineSet routines);

/// The compiled model of `id`: from the cache, else `derive()` is called for
/// the equations, which are compiled and stored. Throws std::runtime_error with
/// the compiler's messages when compilation fails.
std::unique_ptr<runtime::SharedModel> load_compiled_model(const ModelIdentity& id,
                                                          const std::function<ir::System()>& derive,
                                                          const JitOptions& options = {});

/// A System at hand (tests, programs embedding yamsc) compiled with every
/// routine of the ABI, keyed by its generated source.
std::unique_ptr<runtime::SharedModel> load_compiled_model(const ir::System& eq,
                                                          const JitOptions& options = {});

} // namespace yamsc::analysis
