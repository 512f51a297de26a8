#pragma once
// InflowWind's primary input file (OpenFAST v3 to v5, "InflowWind v3.01.*"), as
// InflowWind_ParseInputFileInfo reads it: three header lines, then one entry a
// line, "value(s)  Key  - comment", section lines (--- or ===) between groups,
// and the OutList block closed by END. The entries are kept by key with where they
// are, so that each kind of wind (steady, uniform file, and later full fields)
// reads its own section's entries with located errors; which entries a kind uses
// is its business, not the reader's.
#include <istream>
#include <string>
#include <vector>

namespace yamsc::wind {

struct InflowWindEntry {
    std::string key; // as InflowWind names it (the file's spelling may differ in case)
    std::vector<std::string> values; // the tokens before the key, quotes removed
    std::vector<int> columns;        // 1-based column of each value (key_column if none)
    int line = 0;                    // 1-based
    int key_column = 0;
};

class InflowWindFile {
public:
    std::string source; // the file's path, as given (errors and relative paths)
    std::vector<InflowWindEntry> entries;
    std::vector<InflowWindEntry> out_list; // OutList's channel names, one entry a line
    std::vector<std::string> warnings;     // "source:line:col: warning: ..." (entries not used)
    int last_line = 0;

    /// The entry `key` (case-insensitive), or nullptr.
    const InflowWindEntry* find(const std::string& key) const;
    /// The entry `key`; a located error (the end of the file) without it.
    const InflowWindEntry& entry(const std::string& key) const;
    double number(const std::string& key) const;
    /// The number, or `fallback` when the entry is absent or "default".
    double number_or(const std::string& key, double fallback) const;
    int integer(const std::string& key) const;
    bool flag(const std::string& key) const;
    std::string text(const std::string& key) const;
    /// A path entry relative to the folder of the file (InflowWind's PriPath).
    std::string path(const std::string& key) const;

    /// Throws std::runtime_error "source:line:col: what" at the entry's (first) value.
    [[noreturn]] void fail(const InflowWindEntry& e, const std::string& what) const;
    /// Adds "source:line:col: warning: what" at the entry's first value.
    void warn(const InflowWindEntry& e, const std::string& what);
};

/// Whether the text looks like an InflowWind primary file (a WindType entry in its
/// first lines), to tell it from a wind file of samples.
bool looks_like_inflowwind(std::istream& in);

/// Reads the file: every line after the header an entry (unknown keys warn at
/// their line). Throws std::runtime_error "source:line:col: message".
InflowWindFile read_inflowwind_file(std::istream& in, const std::string& source);

} // namespace yamsc::wind
