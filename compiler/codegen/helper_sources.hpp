#pragma once
// The helper routines generated code calls (LDL^T, RK4), printed from real
// source files (codegen/helpers/*.inc, embedded in the compiler at build time)
// with the output's types, literals, names and linkage put in.
#include "codegen/printer.hpp"
#include "codegen/syntax.hpp"

#include <string>

namespace yamsc::codegen {

/// `ldlt_factor` and `ldlt_solve` (helpers/ldlt.inc) with `linkage` ("" or
/// "static ") before each, the syntax's helper prefix and floating-point type.
std::string ldlt_source(const Syntax& syntax, const std::string& linkage);

/// `<prefix>_rk4_step` (helpers/rk4.inc) for a state of nx values: `api_real`
/// in its signature, the syntax's type for locals and literals.
std::string rk4_source(const Syntax& syntax, const std::string& prefix, const std::string& api_real,
                       const std::string& params_type, int nx);

/// `text` with every whole-identifier occurrence of `word` replaced by `by`.
std::string replace_identifier(const std::string& text, const std::string& word,
                               const std::string& by);

} // namespace yamsc::codegen
