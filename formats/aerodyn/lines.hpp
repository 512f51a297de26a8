#pragma once
// The lines of an AeroDyn input file as OpenFAST's parser sees them, and a cursor
// that reads them in order.
//
// OpenFAST reads the AeroDyn primary file and the airfoil files through
// ProcessComFile: the text from the first '!', '#' or '%' of a line on is a
// comment, blank lines are dropped, and a line starting with '@' is replaced by the
// lines of the file it names (relative to the folder of the file that names it).
// Then each entry is expected in its place ("value  Key  - comment"): an entry a
// version may leave out is skipped when the line holds another key, as OpenFAST does.
// The tokens come from ElastoDyn's tokenizer (elastodyn/file.hpp).
#include "diag/diagnostics.hpp"
#include "elastodyn/file.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace yamsc::aerodyn {

/// Files that include files: an include chain deeper than this is an error.
inline constexpr int max_include_depth = 8;
/// The largest count of rows, nodes, tables or files an AeroDyn file may announce.
inline constexpr int max_count = 100000;

/// One logical line: its tokens, and where it is.
struct Line {
    std::shared_ptr<const diag::SourceFile> file;
    int number = 0; // 1-based line in `file`
    std::vector<elastodyn::Token> tokens;
    diag::Location at(int token = 0) const;
};

/// Reads a file that an '@' line includes; nullptr after reporting why at `at`.
using IncludeReader = std::function<std::shared_ptr<const diag::SourceFile>(
    const std::string& path, const diag::Location& at, diag::Diagnostics& diags)>;

/// Reads included files from the disk (diag::read_text_file).
IncludeReader includes_from_disk();
/// Refuses every include, with an error at the '@' line (text not from a file).
IncludeReader includes_refused();

/// The logical lines of `file`: comments and blank lines removed; '@' lines replaced
/// by the lines of the files they name when `includes` is set, kept as they are
/// otherwise.
std::vector<Line> logical_lines(const std::shared_ptr<const diag::SourceFile>& file,
                                const IncludeReader* includes, diag::Diagnostics& diags);

/// One entry found by the cursor: the value tokens before the key.
struct Entry {
    const Line* line = nullptr;
    std::string key;                      // as written
    std::vector<elastodyn::Token> values; // the tokens before the key (one for scalars)
    diag::Location at() const;            // of the first value
    diag::Location key_at() const;        // of the key
    const std::string& value() const { return values.front().text; }
};

class Cursor {
public:
    Cursor(std::vector<Line> lines, std::shared_ptr<const diag::SourceFile> file,
           diag::Diagnostics& diags);

    /// Skips the lines among the first `count` lines of the file (a banner and a title).
    void skip_header(int count);
    /// The entry `key` if the next line (after section lines of --- or ===) holds it.
    std::optional<Entry> take(std::string_view key);
    /// Like take(), but a missing entry is an error at the line where it is expected;
    /// after it the cursor reads nothing more (no error for every entry that follows).
    std::optional<Entry> expect(std::string_view key);
    /// The next line whatever it holds (a file name, a table row); nullptr at the end
    /// of the file, after reporting that `what` is missing.
    const Line* next(const std::string& what);
    /// The next line without consuming it (section lines skipped); nullptr at the end.
    const Line* peek();

    /// Where the cursor is: the next line, or the end of the file.
    diag::Location here();
    diag::Diagnostics& diags() { return diags_; }
    const std::shared_ptr<const diag::SourceFile>& file() const { return file_; }

    // Values of entries, with located errors (nullopt after one).
    std::optional<double> number(const Entry& e);
    std::optional<int> integer(const Entry& e);
    std::optional<bool> flag(const Entry& e);
    /// nullopt for "default" (any case); `bad` set after an error.
    std::optional<double> number_or_default(const Entry& e, bool& bad);

    // Shorthands: expect(key) and its value.
    std::optional<double> expect_number(std::string_view key);
    std::optional<int> expect_integer(std::string_view key);
    std::optional<bool> expect_flag(std::string_view key);
    std::optional<std::string> expect_text(std::string_view key);

private:
    void skip_sections();

    std::vector<Line> lines_;
    std::size_t pos_ = 0;
    bool lost_ = false; // an entry was missing: the places of the next ones are unknown
    std::shared_ptr<const diag::SourceFile> file_;
    diag::Diagnostics& diags_;
};

/// "default" in any case.
bool is_default(std::string_view text);

/// A count announced by `key` (NumAlf, NumBlNds, ...): an integer from `low` to
/// max_count, else an error at the entry.
std::optional<int> count(Cursor& c, const Entry& e, int low);

} // namespace yamsc::aerodyn
