#pragma once
// The ways HydroDyn and SeaState read their lines, on AeroDyn's cursor (the lines
// of OpenFAST's ProcessComFile, aerodyn/lines.hpp): ParseVar (a value and its key,
// the key checked), ParseAry (a given number of values on the next line, the key
// after them not checked), table header lines skipped unread, and the OUTPUT
// CHANNELS list up to its END line. Every entry read is remembered with its place.
#include "aerodyn/lines.hpp"

#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace yamsc::hydrodyn {

/// The values of one row read as ParseAry reads it, with the line they are on.
struct Values {
    const aerodyn::Line* line = nullptr;
    std::vector<elastodyn::Token> tokens; // the first `n` tokens of the line
    diag::Location at(std::size_t i) const;
};

class EntryReader {
public:
    EntryReader(aerodyn::Cursor& cursor, std::vector<std::pair<std::string, diag::Location>>& where)
        : c_(cursor), where_(where) {}

    aerodyn::Cursor& cursor() { return c_; }
    diag::Diagnostics& diags() { return c_.diags(); }

    /// The entry `key` here (an error if it is not), or an entry a version may leave
    /// out (nullopt, no error, if the line holds another key).
    std::optional<aerodyn::Entry> need(const char* key);
    std::optional<aerodyn::Entry> maybe(const char* key);

    // Values of entries into fields, located errors; nothing happens for nullopt.
    void set(const std::optional<aerodyn::Entry>& e, bool& v);
    void set(const std::optional<aerodyn::Entry>& e, int& v);
    void set(const std::optional<aerodyn::Entry>& e, double& v);
    void set(const std::optional<aerodyn::Entry>& e, std::string& v);
    /// nullopt for "default" (any case, quoted or not).
    void set_or_default(const std::optional<aerodyn::Entry>& e, std::optional<double>& v);

    /// A count `key` from `low` to `high`, else an error at its value.
    std::optional<int> count(const char* key, int low, int high);

    /// The next line's first `n` tokens (section lines skipped before it), as ParseAry
    /// reads them; `key`, when it follows them, is remembered. An error names `what`.
    std::optional<Values> row(const std::string& what, std::size_t n, const char* key = nullptr);
    /// The line of the last row() read (its number, or itself: file and tokens).
    int last_line() const { return last_row_ ? last_row_->number : 0; }
    const aerodyn::Line* last_row() const { return last_row_; }
    /// The same, each token a number.
    std::optional<std::vector<double>> numbers(const std::string& what, std::size_t n,
                                               const char* key = nullptr);
    /// The number of leading tokens of the next line (section lines skipped) that are
    /// numbers, without consuming it; 0 at the end of the file.
    std::size_t leading_numbers();

    /// Whether the next line (section lines skipped) holds `key` as its token `n`.
    bool next_holds(std::size_t n, const char* key);

    /// Skips `n` lines unread (a table's names and units); false at the end of the file.
    bool skip(int n, const std::string& what);

    /// OUTPUT CHANNELS: each line's first word (a quoted one may hold several names)
    /// until a line whose first word starts with END.
    void out_channels(std::vector<std::string>& names, std::vector<int>& lines);

    /// A number token, or an error naming `what` at it.
    std::optional<double> number(const Values& v, std::size_t i, const std::string& what);
    /// A number that must be a whole number (Fortran reads an INTEGER, or NINT of a real
    /// when `round`), within +-1e9.
    std::optional<int> integer(const Values& v, std::size_t i, const std::string& what,
                               bool round = false);
    /// A Fortran LOGICAL: T or F (any case), optionally after a period.
    std::optional<bool> logical(const Values& v, std::size_t i, const std::string& what);

    /// A warning: read, but not modelled.
    void unsupported(const diag::Location& at, const std::string& what);

private:
    std::optional<aerodyn::Entry> seen(std::optional<aerodyn::Entry> e);

    aerodyn::Cursor& c_;
    std::vector<std::pair<std::string, diag::Location>>& where_;
    const aerodyn::Line* last_row_ = nullptr;
};

/// Where `key` was read among `entries` (any case), or `file` without a position.
diag::Location entry_location(const std::vector<std::pair<std::string, diag::Location>>& entries,
                              const std::shared_ptr<const diag::SourceFile>& file,
                              const std::string& key);

/// Runs the `sections` of `reader` in order; stops after one that reported an error, since
/// the places of the next entries are then unsure (the first error is the one to fix).
/// Returns whether all ran without error.
template <class R>
bool read_sections(R& reader, std::initializer_list<void (R::*)()> sections,
                   const diag::Diagnostics& diags, int errors_before) {
    for (auto section : sections) {
        if (diags.error_count() != errors_before) return false;
        (reader.*section)();
    }
    return diags.error_count() == errors_before;
}

/// A file read whole by `Reader(cursor, input).read()`: the input, or nullopt after
/// an error (the reader of each format is this with its own Input and Reader).
template <class Input, class Reader>
std::optional<Input> read_entries(const std::shared_ptr<const diag::SourceFile>& file,
                                  diag::Diagnostics& diags,
                                  const aerodyn::IncludeReader& includes) {
    const int errors = diags.error_count();
    aerodyn::Cursor c(aerodyn::logical_lines(file, &includes, diags), file, diags);
    Input out;
    out.path = file->path();
    out.file = file;
    Reader(c, out).read();
    if (diags.error_count() != errors) return std::nullopt;
    return out;
}

/// Whether a token reads as a Fortran LOGICAL (T, F, .TRUE., false, ...).
std::optional<bool> parse_logical(std::string_view text);

} // namespace yamsc::hydrodyn
