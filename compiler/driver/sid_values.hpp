#pragma once
// `--sid body=file.sid`: values of the shape-integral parameters of a flexible body
// declared with `symbolic modes`, read from a SID file at run time.
#include "driver/values.hpp"
#include "model/model.hpp"

namespace yamsc::driver {

/// Assignments `tower_Me_1_1=...` for every `body=path` of `spec` (comma separated).
/// Throws UserError for an unknown or non-symbolic body, an unreadable or damaged
/// file, a mode count that differs, or a non-zero entry the compiled model has no
/// parameter for (it was zero when the model was compiled).
std::vector<Assignment> sid_parameter_values(const model::Model& m, const std::string& spec);

/// The (body, path) items of `spec`; throws UsageError when one is not `body=path`.
std::vector<std::pair<std::string, std::string>> sid_spec_items(const std::string& spec);

} // namespace yamsc::driver
