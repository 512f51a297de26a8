#pragma once
// Helpers shared by the parser tests: parse a text, list its diagnostics compactly.
#include "parse/parser.hpp"

#include <memory>
#include <optional>
#include <string>

namespace yamsc::test {

inline std::shared_ptr<const diag::SourceFile> make_source(std::string text,
                                                           std::string path = "test.mbd") {
    return std::make_shared<const diag::SourceFile>(std::move(path), std::move(text));
}

struct Parsed {
    std::optional<ast::ModelFile> file;
    diag::Diagnostics diags;
};

inline Parsed parse_text(std::string text) {
    Parsed result;
    result.file = parse::parse_model(make_source(std::move(text)), result.diags);
    return result;
}

/// "L:C: message [kind]" per diagnostic, one per line.
inline std::string brief(const diag::Diagnostics& diags) {
    std::string out;
    for (const diag::Diagnostic& d : diags.all()) {
        out += std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + ": " + d.message +
               " [" + std::string(diag::kind_name(d.kind)) + "]\n";
    }
    return out;
}

/// Parses an expression given as the right-hand side of `param a = ...`.
inline std::optional<ast::Expr> parse_expr(const std::string& text, diag::Diagnostics& diags) {
    return parse::parse_expression(make_source(text, "expr"), diags);
}

} // namespace yamsc::test
