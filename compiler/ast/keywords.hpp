#pragma once
// The words of the model language, defined once: the parser's "did you mean"
// suggestions and the checker's reserved names (model/names.cpp) both come from
// here. They must agree with the keyword rules of grammar/model_grammar.hpp.
#include <string>
#include <vector>

namespace yamsc::ast {

/// The words that start a top-level statement (docs/language.md).
const std::vector<std::string>& statement_keywords();
/// The words that start an item of a flexible body block (besides `key = value`).
const std::vector<std::string>& flexible_item_keywords();
/// The words that start an item of a beam block (besides `key = value`).
const std::vector<std::string>& beam_item_keywords();
/// The joint steps.
const std::vector<std::string>& joint_step_keywords();
/// Every keyword of the language (statements, block items, steps, `on`, `in`, `deg`, ...):
/// reserved, no user name may take one. Words that are keywords only in one place
/// (`tip` and `node` after a flexible body, `modes` inside its block) stay usable
/// as names.
const std::vector<std::string>& language_keywords();
/// The names the language predefines (`ground`, `t`, `pi`, the kinematic functions): not
/// keywords of the grammar, but no user name may take them either.
const std::vector<std::string>& predefined_names();

} // namespace yamsc::ast
