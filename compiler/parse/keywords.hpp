#pragma once
// The words of the model language, for "did you mean" suggestions and for the checker's list of
// reserved names. They must agree with the keyword rules of grammar/model_grammar.hpp.
#include <string>
#include <vector>

namespace yamsc::parse {

/// The words that start a top-level statement (docs/language.md).
const std::vector<std::string>& statement_keywords();
/// The words that start an item of a flexible body block (besides `key = value`).
const std::vector<std::string>& flexible_item_keywords();
/// The words that start an item of a beam block (besides `key = value`).
const std::vector<std::string>& beam_item_keywords();
/// The joint steps.
const std::vector<std::string>& joint_step_keywords();
/// Every keyword of the language (statements, block items, steps, `on`, `in`, `deg`, ...).
const std::vector<std::string>& language_keywords();

} // namespace yamsc::parse
