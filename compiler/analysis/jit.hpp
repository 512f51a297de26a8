#pragma once
// Models compiled on the fly: `yamsc sim` and `yamsc lin` run the model's
// generated C++ (not an interpreter). The source is compiled with the system
// C++ compiler into a shared library, cached by the digest of its text, and
// loaded through the C ABI of runtime/include/yamsc/abi_export.hpp.
#include "ir/system.hpp"

#include <yamsc/dynamic_model.hpp>

#include <functional>
#include <memory>

namespace yamsc::driver {

struct JitOptions {
    std::string compiler;  // empty: $YAMSC_CXX, $CXX, the compiler yamsc was built with, c++
    std::string cache_dir; // empty: $YAMSC_CACHE_DIR, $XDG_CACHE_HOME/yamsc, ~/.cache/yamsc
    std::function<void(const std::string&)> progress;
};

/// The C++ translation unit that exports a model: generated source + ABI shim.
std::string shared_model_source(const ir::System& eq);

/// Compiles (or finds in the cache) and loads the model. Throws std::runtime_error
/// with the compiler's messages when compilation fails.
std::unique_ptr<runtime::SharedModel> load_compiled_model(const ir::System& eq,
                                                          const JitOptions& options = {});

} // namespace yamsc::driver
