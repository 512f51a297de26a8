#pragma once
// The model-language parser: `.mbd` source text -> ast::ModelFile.
#include "ast/ast.hpp"
#include "diag/diagnostics.hpp"

#include <memory>
#include <optional>
#include <string_view>

namespace yamsc::parse {

/// Parses one .mbd source. Reports every syntax error it can into `diags` (kind
/// diag::Kind::Syntax or Limit) and returns std::nullopt if there was any error. Never throws for
/// bad input, never crashes or hangs.
std::optional<ast::ModelFile> parse_model(std::shared_ptr<const diag::SourceFile> source,
                                          diag::Diagnostics& diags);

/// Parses a lone expression with the syntax of the model language (e.g. the value of
/// `--set theta_t=5deg`); `source` holds just that text. Reports errors like parse_model().
std::optional<ast::Expr> parse_expression(std::shared_ptr<const diag::SourceFile> source,
                                          diag::Diagnostics& diags);

} // namespace yamsc::parse
