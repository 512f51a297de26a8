#pragma once
// Reading an input file whole, as every stage that reads files needs it: a
// folder or an unreadable path is an error at `where`, and so is a file larger
// than any input yamsc reads, found before it is held in memory (/dev/zero or
// an endless pipe end in an error, not in exhausted memory).
#include "diag/diagnostics.hpp"

#include <cstddef>
#include <memory>
#include <string>

namespace yamsc::diag {

/// No reader accepts more than 256 MiB (SID files; models far less).
inline constexpr std::size_t max_input_bytes = std::size_t{256} << 20;

/// The file's text, or nullptr after reporting why into `diags` at `where`.
std::shared_ptr<const SourceFile> read_text_file(const std::string& path, Diagnostics& diags,
                                                 const Location& where = {});

} // namespace yamsc::diag
