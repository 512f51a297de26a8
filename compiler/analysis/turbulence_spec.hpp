#pragma once
// `yamsc turbulence`'s inputs as the generator's spec: a TurbSim input file's
// entries (formats/wind/turbsim_input.hpp), each replaced by the option given.
#include "driver/commands.hpp"

#include <yamsc/wind/turbulence.hpp>

#include <string>
#include <vector>

namespace yamsc::analysis {

/// Throws diag::UserError (the file's located errors) or diag::UsageError (an option
/// missing without a file). `warnings` receives the file's located warnings.
runtime::TurbulenceSpec turbulence_spec(const driver::TurbulenceOptions& o,
                                        std::vector<std::string>& warnings);

} // namespace yamsc::analysis
