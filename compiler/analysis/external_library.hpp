#pragma once
// The implementation of a model's external functions (`external ...`,
// docs/language.md) for `yamsc sim`, `lin`, `eval` and `trim`: a shared
// library given as `--external lib.so`, or a C or C++ source given as
// `--external file.c|file.cpp`, compiled against the generated prototypes (a
// wrong signature is a compile error) into the JIT's cache, keyed by the
// source's and the prototypes' digests. The library is loaded with
// RTLD_GLOBAL before the model's, whose calls then bind to it, and stays
// loaded for the life of the process.
#include "analysis/jit.hpp"
#include "model/model.hpp"

#include <string>
#include <vector>

namespace yamsc::analysis {

struct ExternalLibrary {
    std::string path; // the shared library loaded
    /// One line per external whose derivatives are central differences
    /// ("drag: derivatives by central differences"), for the command's output.
    std::vector<std::string> notes;
};

/// Loads the implementation of `m`'s externals from `spec`. Reports into
/// `diags`, at each external's declaration, a missing --external and every
/// function the library lacks (nullopt then). Throws diag::UserError when the
/// source does not compile or the library does not load, diag::UsageError when
/// `spec` is given for a model without externals.
std::optional<ExternalLibrary> load_external_library(const model::Model& m, const std::string& spec,
                                                     const JitOptions& options,
                                                     diag::Diagnostics& diags);

} // namespace yamsc::analysis
