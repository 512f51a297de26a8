#pragma once
// The writer of Standard Input Data (SID) files, in the format of docs/sid-format.md.
#include "sid/sid.hpp"

#include <string>

namespace yamsc::sid {

/// The SID as text: every block of `sid`, numbers with the fewest digits that read back
/// exactly, so that read_sid(write_sid(sid)) == sid. A block whose numbers do not fit its
/// `structure` (e.g. a non-symmetric block marked symmetric) is written as full (3). Mode
/// names and rframe are written on one line (line breaks become spaces); the reader trims
/// blanks around them. Throws diag::InternalError if a Taylor's arrays do not match its
/// dimensions (a bug of the code that built it).
std::string write_sid(const Sid& sid);

} // namespace yamsc::sid
