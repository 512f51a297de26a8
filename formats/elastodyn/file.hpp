#pragma once
// A reader for OpenFAST input files in the ElastoDyn style: one value per line
// followed by its key and an optional comment ("  87.6   TowerHt  - Height (m)"),
// and tables of numbers under a header row of column names and a row of units.
// Keys are case-insensitive; the first line holding a key wins. Every getter reports
// a located diagnostic and returns nullopt when the key is missing or the value bad.
#include "diag/diagnostics.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace yamsc::elastodyn {

struct EdTable {
    std::vector<std::string> columns;      // names from the header row
    std::vector<std::vector<double>> rows; // rows x columns
    std::vector<int> lines;                // source line of each row
    int header_line = 0;                   // the line of the column names
    /// Index of a column (case-insensitive), or -1.
    int column(std::string_view name) const;
};

class ElastoDynFile {
public:
    explicit ElastoDynFile(std::shared_ptr<const diag::SourceFile> file);

    bool has(std::string_view key) const { return find(key) != nullptr; }
    std::optional<double> get_double(std::string_view key, diag::Diagnostics& diags) const;
    std::optional<int> get_int(std::string_view key, diag::Diagnostics& diags) const;
    std::optional<bool> get_bool(std::string_view key, diag::Diagnostics& diags) const;
    /// The value as text, without its quotes.
    std::optional<std::string> get_string(std::string_view key, diag::Diagnostics& diags) const;
    /// The `rows` rows of numbers under the header row whose first name is `first_column`
    /// (a row of units in parentheses after the header is skipped). Each row must hold a
    /// number for every column; a missing row, or one more numeric row, is an error.
    std::optional<EdTable> get_table(std::string_view first_column, int rows,
                                     diag::Diagnostics& diags) const;

    /// Where `key` is (its value's column), or the file without a line if absent.
    diag::Location location(std::string_view key) const;
    const std::shared_ptr<const diag::SourceFile>& file() const { return file_; }

private:
    struct Entry {
        std::string key;   // as written
        std::string value; // first token, quotes removed
        int line = 0;
        int col = 0; // of the value
    };
    const Entry* find(std::string_view key) const;
    void missing(std::string_view key, diag::Diagnostics& diags) const;

    std::shared_ptr<const diag::SourceFile> file_;
    std::vector<Entry> entries_;
};

/// A blank- or comma-separated token of an ElastoDyn line; "..." and '...' are one
/// token (file names with blanks), without the quotes.
struct Token {
    std::string text;
    int col = 0; // 1-based column of its first character
    bool quoted = false;
};

/// The tokens of one line.
std::vector<Token> tokenize(std::string_view line);

/// Whether two keys are the same, ignoring case (as OpenFAST compares them).
bool same_key(std::string_view a, std::string_view b);

/// Parses a whole token as a number (Fortran 'D' exponents accepted).
std::optional<double> parse_number(std::string_view token);

} // namespace yamsc::elastodyn
