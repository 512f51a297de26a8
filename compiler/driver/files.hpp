#pragma once
// Files: reading sources with a located error, and the digest that identifies
// a model's source in generated headers. Outputs are checked against the
// inputs by driver/outputs.hpp and written by yamsc_files'
// write_file_atomically (yamsc/atomic_file.hpp).
#include "diag/diagnostics.hpp"

#include <optional>
#include <string>

namespace yamsc::driver {

/// Reads a whole file; reports an Io diagnostic and returns nullopt on failure.
std::shared_ptr<const diag::SourceFile> read_source(const std::string& path,
                                                    diag::Diagnostics& diags);

/// Hex digest (FNV-1a, 64 bit) of a text.
std::string digest(const std::string& text);

} // namespace yamsc::driver
