#pragma once
// Diagnostics: located, user-facing errors and warnings collected by every stage.
// A stage reports as many errors as it can find and never throws for user errors;
// the driver renders them as `file:line:col: error: message [kind]` with the source
// line and a caret.
#include "diag/errors.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace yamsc::diag {

enum class Kind {
#define X(id, name, what) id,
#include "diag_kinds.def"
#undef X
};

/// Short name of a kind, as printed in brackets after a message.
std::string_view kind_name(Kind kind);
/// All kinds, in declaration order (for tests and documentation).
std::vector<Kind> all_kinds();

/// A source text with its path, kept alive by every location that points into it.
class SourceFile {
public:
    SourceFile(std::string path, std::string text);
    const std::string& path() const { return path_; }
    const std::string& text() const { return text_; }
    /// The text of line `line` (1-based) without its newline; empty if out of range.
    std::string_view line(int line) const;
    /// The number of lines; a text ending with a newline has an empty last line after it.
    int line_count() const { return static_cast<int>(line_starts_.size()); }

private:
    std::string path_;
    std::string text_;
    std::vector<std::size_t> line_starts_;
};

/// A position in a source file: 1-based line and column. line == 0 means "no position".
struct Location {
    std::shared_ptr<const SourceFile> file;
    int line = 0;
    int col = 0;
};

enum class Severity { error, warning, note };

struct Diagnostic {
    Severity severity = Severity::error;
    Kind kind = Kind::Syntax;
    Location loc;
    std::string message;
};

/// The sink every stage reports into.
class Diagnostics {
public:
    void error(Kind kind, Location loc, std::string message);
    void warning(Kind kind, Location loc, std::string message);
    void note(Location loc, std::string message);

    bool has_errors() const { return errors_ > 0; }
    int error_count() const { return errors_; }
    const std::vector<Diagnostic>& all() const { return list_; }

    /// All diagnostics rendered for a terminal, in the order they were reported.
    std::string render() const;

private:
    std::vector<Diagnostic> list_;
    int errors_ = 0;
};

/// One diagnostic as text: `file:line:col: error: message [kind]`, the line, a caret.
std::string render(const Diagnostic& d);

/// The candidate closest to `name` by edit distance, or "" if none is close enough
/// to be a plausible misspelling.
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

/// " (did you mean 'x'?)" or "".
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

} // namespace yamsc::diag
