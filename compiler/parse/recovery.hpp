#pragma once
// Where parsing resumes after a syntax error: the rest of the statement is skipped.
#include <cstddef>
#include <string_view>

namespace yamsc::parse {

/// The number of bytes of `rest` (the text from the error on) that belong to the broken
/// statement: up to the next newline or `;` outside brackets, skipping whole `{...}` blocks and
/// `(...)` groups that open in it, strings and comments. With `inside_block`, an unmatched `}`
/// also ends it (it closes the enclosing block). The newline, `;` or `}` is not included.
std::size_t statement_rest_length(std::string_view rest, bool inside_block);

} // namespace yamsc::parse
