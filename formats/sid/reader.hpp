#pragma once
// The reader of Standard Input Data (SID) files (docs/sid-format.md). It accepts what other
// tools write (any order of entries, optional blocks left out, unknown blocks skipped with a
// warning) and rejects damaged files with located errors. It never throws for bad input and
// bounds what a file may make it allocate (sid/read_context.hpp).
#include "diag/diagnostics.hpp"
#include "sid/sid.hpp"

#include <memory>
#include <optional>
#include <string>

namespace yamsc::sid {

/// Reads the SID in `file`. Reports every problem it finds into `diags` (errors of kinds
/// Syntax, InvalidValue, MissingProperty, NotSupported, Limit; warnings for what it skips or
/// assumes) and returns std::nullopt if there was any error.
std::optional<Sid> read_sid(const std::shared_ptr<const diag::SourceFile>& file,
                            diag::Diagnostics& diags);

/// Reads the file at `path` (an Io error if it cannot be read), then as read_sid().
std::optional<Sid> read_sid_file(const std::string& path, diag::Diagnostics& diags);

} // namespace yamsc::sid
