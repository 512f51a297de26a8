#pragma once
// Finds and loads the derivation module (derivation/derivation.hpp) the first
// time a command needs equations; a process that never derives never loads
// GiNaC.
#include "derivation/derivation.hpp"

#include <string>

namespace yamsc::driver {

/// Derives and lowers `request.model` through the module into `result.system`.
/// Model errors go to `diags` (no System then); an internal failure of the module is thrown again
/// here as diag::InternalError, any other as std::runtime_error. Throws
/// diag::InternalError when no module of this build can be found.
/// `result` also carries the module's stage times.
void derive_through_module(const derivation::DerivationRequest& request, diag::Diagnostics& diags,
                           derivation::DerivationResult& result);

/// The module this process uses (or would use): its path, "" when none is
/// found. YAMSC_DERIVATION_MODULE chooses a file; otherwise, in order, beside
/// the program (or the library this code is in), in ../lib/yamsc of an
/// installed tree, then where `cmake --install` puts it and in the build tree
/// (the build tree first for a program that is still in it).
std::string derivation_module_path();

/// The folder of the file this code was loaded from: the yamsc program, or the
/// Python module that links the driver ("" when it cannot be told). Whatever
/// ships beside the program (the derivation module, the FMI unit's libraries)
/// is found from it.
std::string own_folder();

} // namespace yamsc::driver
