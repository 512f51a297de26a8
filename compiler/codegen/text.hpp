#pragma once
// Safe spelling of model text (names, docs, paths) in generated code: nothing
// a model file contains can end a comment, end a string or splice a line.
#include <string>
#include <string_view>

namespace yamsc::codegen {

/// A C/C++ string literal with the same bytes: quotes, backslashes, `?` (no
/// trigraphs) and every byte outside printable ASCII escaped.
std::string c_string_literal(std::string_view text);

/// `text` in double quotes for a `//` comment: control characters become spaces,
/// so the comment stays on its line, and the closing quote keeps a final
/// backslash from splicing the next line into the comment.
std::string comment_quote(std::string_view text);

bool is_c_identifier(std::string_view text);

/// One or more identifiers joined by `::` (a C++ namespace name).
bool is_cpp_namespace(std::string_view text);

} // namespace yamsc::codegen
