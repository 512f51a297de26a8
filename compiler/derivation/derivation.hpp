#pragma once
// The derivation (Kane's method in GiNaC, then the one import into the IR) as a
// loadable module: the checked model in, the ir::System out. GiNaC and CLN are
// linked into that module only, so a command that needs no derivation (a `sim`
// whose compiled model is cached, `check`, `--version`) never loads them: their
// start-up alone is about 3.5 ms of every process (docs/benchmarks.md).
//
// Both sides are built from the same sources in the same build, so the types
// below cross the boundary as they are; `derivation_identity()` guards against
// a module of another build. No exception crosses it either: the module
// reports a failure in `DerivationResult` and the loader throws it again.
#include "diag/diagnostics.hpp"
#include "ir/system.hpp"
#include "model/model.hpp"

#include <optional>
#include <string>

namespace yamsc::derivation {

struct DerivationRequest {
    /// The checked model with its external channels (model::with_external_channels).
    const model::Model* model = nullptr;
    /// false: M is not assembled, only M a (the tangent form).
    bool mass_matrix = true;
    std::string source_path;   // recorded in the System
    std::string source_digest; // the model and its data by content
};

struct DerivationResult {
    enum class Failure { none, internal, other };
    /// Empty when the model has errors (reported into the Diagnostics).
    std::optional<ir::System> system;
    Failure failure = Failure::none;
    std::string message;         // what the exception said, with `failure`
    double derive_seconds = 0.0; // Kane's method (GiNaC)
    double lower_seconds = 0.0;  // the import into the IR
};

/// The module's entry: derives and lowers, reporting model errors into `diags`.
using DeriveFunction = void (*)(const DerivationRequest&, diag::Diagnostics&, DerivationResult&);
/// The build a module or a loader comes from (version and the sizes of the
/// types that cross): equal on both sides or the module is refused.
using IdentityFunction = const char* (*)();

inline constexpr const char* derive_symbol = "yamsc_derive_system";
inline constexpr const char* identity_symbol = "yamsc_derivation_identity";
inline constexpr const char* module_file_name = "libyamsc-derivation.so";

/// This side's identity (compiled into both the module and its loader).
std::string derivation_identity();

} // namespace yamsc::derivation
