#pragma once
// The summary of `yamsc batch`: one line per case (row, id, status, final
// values or error, wall time), written by a run or a shard and read back by
// `yamsc batch merge`; and the record that marks a case done.
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::analysis {

struct CaseSummary {
    int row = 0;    // 1-based data row of the manifest
    std::string id; // as written in the manifest (may be invalid for a bad row)
    bool ok = false;
    std::string final;   // ok: "name=value,..." of the last output row (time included)
    std::string message; // failed: the located error, on one line
    double wall_s = 0;   // the run's wall time (of the run that made the result)
};

/// The header of every summary file.
extern const char* const summary_header;

std::string summary_line(const CaseSummary& s);
/// A summary file's text: header, then the cases in the given order.
std::string summary_text(const std::vector<CaseSummary>& cases);
/// Reads a summary file; throws UserError naming the file and line when malformed.
std::vector<CaseSummary> read_summary(const std::string& path);

/// The record of a finished case (`OUTDIR/.records/<id>`): the digest of the
/// row it ran, and its summary.
std::string record_text(const std::string& digest, const CaseSummary& s);
/// The summary of a record whose digest is `digest`; nullopt when the record
/// is missing, unreadable or from another row content.
std::optional<CaseSummary> read_record(const std::string& path, const std::string& digest);

/// One line of text (newlines of a multi-line message become " | ").
std::string one_line(const std::string& text);

} // namespace yamsc::analysis
