#include "diag/diagnostics.hpp"

#include "text/utf8.hpp"

#include <algorithm>
#include <cctype>

namespace yamsc::diag {

// ---------------------------------------------------------------- kinds

std::string_view kind_name(Kind kind) {
    switch (kind) {
#define X(id, name, what)                                                                          \
    case Kind::id:                                                                                 \
        return name;
#include "diag_kinds.def"
#undef X
    }
    return "unknown";
}

std::vector<Kind> all_kinds() {
    return {
#define X(id, name, what) Kind::id,
#include "diag_kinds.def"
#undef X
    };
}

// ---------------------------------------------------------------- source files

SourceFile::SourceFile(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < text_.size(); ++i) {
        if (text_[i] == '\n') line_starts_.push_back(i + 1);
    }
}

std::string_view SourceFile::line(int line) const {
    if (line < 1 || static_cast<std::size_t>(line) > line_starts_.size()) return {};
    const std::size_t begin = line_starts_[static_cast<std::size_t>(line) - 1];
    std::size_t end = static_cast<std::size_t>(line) < line_starts_.size()
                          ? line_starts_[static_cast<std::size_t>(line)] - 1
                          : text_.size();
    if (end > begin && text_[end - 1] == '\r') --end;
    return std::string_view(text_).substr(begin, end - begin);
}

// ---------------------------------------------------------------- collection

void Diagnostics::error(Kind kind, Location loc, std::string message) {
    list_.push_back(Diagnostic{Severity::error, kind, std::move(loc), std::move(message)});
    ++errors_;
}

void Diagnostics::warning(Kind kind, Location loc, std::string message) {
    list_.push_back(Diagnostic{Severity::warning, kind, std::move(loc), std::move(message)});
}

void Diagnostics::note(Location loc, std::string message) {
    list_.push_back(Diagnostic{Severity::note, Kind::Syntax, std::move(loc), std::move(message)});
}

std::string Diagnostics::render() const {
    std::string out;
    for (const Diagnostic& d : list_) out += diag::render(d);
    return out;
}

// ---------------------------------------------------------------- rendering

namespace {

std::string_view severity_word(Severity s) {
    switch (s) {
    case Severity::error:
        return "error";
    case Severity::warning:
        return "warning";
    case Severity::note:
        return "note";
    }
    return "error";
}

/// The quoted source line and the caret line under it. Control characters and invalid UTF-8
/// show as '?'; tabs are kept in both lines so that the caret lines up; a very long line is
/// shown as a window around the caret.
std::string quote_line(std::string_view line, int col) {
    constexpr std::size_t window = 160;
    const std::size_t caret = col > 0 ? static_cast<std::size_t>(col) - 1 : 0;
    std::size_t begin = 0;
    std::size_t end = line.size();
    if (line.size() > window) {
        begin = std::min(caret > window / 2 ? caret - window / 2 : 0, line.size());
        end = std::min(line.size(), begin + window);
        const auto continuation = [&](std::size_t i) {
            return i < line.size() && text::utf8_continuation(static_cast<unsigned char>(line[i]));
        };
        while (begin > 0 && continuation(begin)) --begin;
        while (end < line.size() && continuation(end)) ++end;
    }
    std::string shown = begin > 0 ? "..." : "";
    std::string padding(shown.size(), ' ');
    for (std::size_t i = begin; i < end;) {
        const auto c = static_cast<unsigned char>(line[i]);
        std::size_t n = 1;
        if (c == '\t') {
            shown += '\t';
        } else if (c < 0x20 || c == 0x7F) {
            shown += '?';
        } else if (c < 0x80) {
            shown += static_cast<char>(c);
        } else if ((n = text::utf8_sequence_length(line.substr(i))) > 0) {
            shown.append(line.substr(i, n));
        } else {
            n = 1;
            shown += '?';
        }
        if (i < caret) padding += c == '\t' ? '\t' : ' ';
        i += n;
    }
    if (end < line.size()) shown += "...";
    if (caret > end) padding.append(caret - std::max(end, begin), ' ');
    return "  " + shown + "\n  " + padding + "^\n";
}

} // namespace

std::string render(const Diagnostic& d) {
    std::string out;
    if (d.loc.file) {
        out += d.loc.file->path();
        out += ':';
        if (d.loc.line > 0) {
            out += std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + ":";
        }
        out += ' ';
    }
    out += severity_word(d.severity);
    out += ": ";
    out += d.message;
    if (d.severity != Severity::note) {
        out += " [";
        out += kind_name(d.kind);
        out += ']';
    }
    out += '\n';
    if (d.loc.file && d.loc.line > 0) {
        // A position just past the last line (the end of a file that ends with a newline)
        // quotes that empty line.
        if (d.loc.line <= d.loc.file->line_count())
            out += quote_line(d.loc.file->line(d.loc.line), d.loc.col);
    }
    return out;
}

// ---------------------------------------------------------------- suggestions

namespace {

std::string lowercase(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

/// Optimal string alignment distance: insertions, deletions, substitutions and transpositions
/// of adjacent characters each cost 1.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                current[j] = std::min(current[j], before[j - 2] + 1);
            }
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

} // namespace

std::string closest_name(std::string_view name, const std::vector<std::string>& candidates) {
    constexpr std::size_t longest_considered = 64;
    if (name.empty() || name.size() > longest_considered) return {};
    const std::string lower = lowercase(name);
    // A plausible misspelling is at most one edit per three characters away, and never
    // as far away as the name is long (so `x` does not suggest `y`).
    const std::size_t allowed = std::max<std::size_t>(1, name.size() / 3);
    std::string best;
    std::size_t best_distance = allowed + 1;
    for (const std::string& candidate : candidates) {
        if (candidate == name) continue;
        const std::string candidate_lower = lowercase(candidate);
        if (candidate_lower == lower) return candidate; // differs only in case
        const std::size_t length_gap = candidate.size() > name.size()
                                           ? candidate.size() - name.size()
                                           : name.size() - candidate.size();
        if (length_gap > allowed) continue;
        const std::size_t d = edit_distance(lower, candidate_lower);
        if (d < best_distance && d < name.size()) {
            best = candidate;
            best_distance = d;
        }
    }
    return best;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates) {
    const std::string best = closest_name(name, candidates);
    return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

} // namespace yamsc::diag
