#pragma once
// OpenFAST's binary output (`.outb`), as NWTC_IO's WrBinFAST writes it and
// ReadFASTbin reads it: little-endian, a header (format id, channel count, step
// count, time scaling, channel scaling, description, names and units of time and
// every channel), then the samples row by row. All four format ids are read:
//   1  time packed in int32 with a slope and offset, channels in int16
//   2  time from the first time and step, channels in int16 (names 10 characters)
//   3  time from the first time and step, channels as float64 (no scaling)
//   4  as 2, with the length of names and units in the header (OpenFAST's default
//      since v3; 3 when the uncompressed output is asked for)
// A packed value v is (v - offset) / slope, the offsets and slopes being float32
// as written, in double arithmetic (as openfast_toolbox reads them). Columns are
// named `NAME_[unit]` as read_table names an `.out` file's. Bytes after the
// announced samples are ignored, as OpenFAST's ReadFASTbin and openfast_toolbox do.
#include "table/table.hpp"

#include <string>

namespace yamsc::table {

/// Throws diag::UserError naming the file and the byte offset of the bad field.
Table read_openfast_binary(const std::string& path);

/// The same for bytes in memory; `name` is used in messages.
Table parse_openfast_binary(const std::string& bytes, const std::string& name);

} // namespace yamsc::table
