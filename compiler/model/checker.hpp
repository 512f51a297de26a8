#pragma once
// The checker: AST -> checked model. Resolves every name, builds the body tree,
// validates every expression against what may appear where, and reports all
// errors it finds (never stops at the first one).
#include "model/data_source.hpp"
#include "model/model.hpp"

namespace yamsc::model {

/// Returns the checked model, or nullopt when an error was reported. The data a
/// flexible body names (SID, beam files) comes from `data`; data::check_model
/// gives it the files beside the model.
std::optional<Model> check(const ast::ModelFile& file, DataSource& data, diag::Diagnostics& diags);

} // namespace yamsc::model
