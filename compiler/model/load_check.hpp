#pragma once
// The `load` declarations checked against the kinds of load_kinds.hpp: kind,
// roles and what each is bound to (located errors with suggestions).
#include "diag/diagnostics.hpp"
#include "model/model.hpp"
#include "model/names.hpp"

#include <vector>

namespace yamsc::model {

/// `model`'s inputs, parameters and outputs are declared (its outputs checked).
std::vector<LoadBlock> check_load_blocks(const ast::ModelFile& file, const Model& model,
                                         const SymbolTable& names, diag::Diagnostics& diags);

/// `text` (the model's source) without its `load` statements, each from its
/// keyword to the end of the line of its `}`, except those with a body role
/// (their mesh channels are equations): the others are run-time metadata, so
/// the digest of what the code is generated from leaves them out (models that
/// differ only in them have the same generated code and cache entries).
std::string without_load_statements(const std::string& text, const Model& model);

} // namespace yamsc::model
