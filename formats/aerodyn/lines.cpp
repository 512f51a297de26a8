#include "aerodyn/lines.hpp"

#include "diag/read_text.hpp"

#include <cctype>
#include <cmath>
#include <filesystem>

namespace yamsc::aerodyn {

namespace fs = std::filesystem;
using diag::Kind;
using elastodyn::Token;

namespace {

bool is_word(const Token& t) {
    return !t.quoted && !t.text.empty() && std::isalpha(static_cast<unsigned char>(t.text[0]));
}

bool is_section(const Line& l) {
    const std::string& t = l.tokens.front().text;
    return !l.tokens.front().quoted && t.size() >= 3 &&
           (t.compare(0, 3, "---") == 0 || t.compare(0, 3, "===") == 0);
}

/// The text of a line before its first comment character, as OpenFAST's ReadLine cuts it.
std::string_view before_comment(std::string_view text) {
    const std::size_t end = text.find_first_of("!#%");
    return end == std::string_view::npos ? text : text.substr(0, end);
}

void add_lines(const std::shared_ptr<const diag::SourceFile>& file, const IncludeReader* includes,
               int depth, std::vector<Line>& out, diag::Diagnostics& diags) {
    for (int n = 1; n <= file->line_count(); ++n) {
        const std::string_view text = before_comment(file->line(n));
        const std::size_t first = text.find_first_not_of(" \t\r");
        if (first == std::string_view::npos) continue;
        if (includes && text[first] == '@') {
            const std::vector<Token> name = elastodyn::tokenize(text.substr(first + 1));
            const int col = static_cast<int>(first) + 2;
            const diag::Location at{file, n, name.empty() ? col : name[0].col + col - 1};
            if (name.empty()) {
                diags.error(Kind::MissingProperty, at, "'@' names no file to include");
                continue;
            }
            if (depth >= max_include_depth) {
                diags.error(Kind::Limit, at,
                            "files include files more than " + std::to_string(max_include_depth) +
                                " deep");
                continue;
            }
            fs::path path(name[0].text);
            if (path.is_relative()) path = fs::path(file->path()).parent_path() / path;
            if (auto included = (*includes)(path.lexically_normal().string(), at, diags))
                add_lines(included, includes, depth + 1, out, diags);
            continue;
        }
        Line line{file, n, elastodyn::tokenize(text)};
        if (!line.tokens.empty()) out.push_back(std::move(line));
    }
}

} // namespace

diag::Location Line::at(int token) const {
    if (token < 0 || token >= static_cast<int>(tokens.size())) return {file, number, 1};
    return {file, number, tokens[static_cast<std::size_t>(token)].col};
}

IncludeReader includes_refused() {
    return [](const std::string&, const diag::Location& at, diag::Diagnostics& diags) {
        diags.error(Kind::Io, at, "this file may not include files ('@')");
        return std::shared_ptr<const diag::SourceFile>();
    };
}

IncludeReader includes_from_disk() {
    return [](const std::string& path, const diag::Location& at, diag::Diagnostics& diags) {
        return diag::read_text_file(path, diags, at);
    };
}

std::vector<Line> logical_lines(const std::shared_ptr<const diag::SourceFile>& file,
                                const IncludeReader* includes, diag::Diagnostics& diags) {
    std::vector<Line> out;
    add_lines(file, includes, 0, out, diags);
    return out;
}

diag::Location Entry::at() const {
    return values.empty() ? key_at() : diag::Location{line->file, line->number, values[0].col};
}

diag::Location Entry::key_at() const {
    for (const Token& t : line->tokens)
        if (elastodyn::same_key(t.text, key)) return {line->file, line->number, t.col};
    return line->at();
}

Cursor::Cursor(std::vector<Line> lines, std::shared_ptr<const diag::SourceFile> file,
               diag::Diagnostics& diags)
    : lines_(std::move(lines)), file_(std::move(file)), diags_(diags) {}

void Cursor::skip_header(int count) {
    while (pos_ < lines_.size() && lines_[pos_].file == file_ && lines_[pos_].number <= count)
        ++pos_;
}

void Cursor::skip_sections() {
    while (pos_ < lines_.size() && is_section(lines_[pos_])) ++pos_;
}

const Line* Cursor::peek() {
    if (lost_) return nullptr;
    skip_sections();
    return pos_ < lines_.size() ? &lines_[pos_] : nullptr;
}

diag::Location Cursor::here() {
    if (const Line* l = peek()) return l->at();
    const int last = file_->line_count();
    return {file_, std::max(last, 1), 1};
}

std::optional<Entry> Cursor::take(std::string_view key) {
    if (lost_) return std::nullopt;
    const Line* l = peek();
    if (!l) return std::nullopt;
    const std::vector<Token>& t = l->tokens;
    Entry e;
    e.line = l;
    if (is_word(t[0]) && elastodyn::same_key(t[0].text, key) && t.size() >= 2) {
        // "Key  value": OpenFAST accepts the name first too.
        e.key = t[0].text;
        e.values = {t[1]};
    } else {
        std::size_t k = 1;
        while (k < t.size() && !is_word(t[k])) ++k;
        if (k >= t.size() || !elastodyn::same_key(t[k].text, key)) return std::nullopt;
        e.key = t[k].text;
        e.values.assign(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(k));
    }
    ++pos_;
    return e;
}

std::optional<Entry> Cursor::expect(std::string_view key) {
    if (lost_) return std::nullopt;
    if (auto e = take(key)) return e;
    const Line* l = peek();
    lost_ = true;
    std::string found;
    if (l) {
        for (const Token& t : l->tokens)
            if (&t != &l->tokens.front() && is_word(t)) {
                found = " (this line holds '" + t.text + "')";
                break;
            }
        diags_.error(Kind::MissingProperty, l->at(),
                     "expected the entry '" + std::string(key) + "' here" + found);
    } else {
        diags_.error(Kind::MissingProperty, here(),
                     "the file ends before the entry '" + std::string(key) + "'");
    }
    return std::nullopt;
}

const Line* Cursor::next(const std::string& what) {
    if (lost_) return nullptr;
    if (pos_ < lines_.size()) return &lines_[pos_++];
    lost_ = true;
    diags_.error(Kind::MissingProperty, here(), "the file ends before " + what);
    return nullptr;
}

bool is_default(std::string_view text) {
    return elastodyn::same_key(text, "default");
}

std::optional<double> Cursor::number(const Entry& e) {
    auto v = elastodyn::parse_number(e.value());
    if (!v)
        diags_.error(Kind::InvalidValue, e.at(),
                     "'" + e.key + "' must be a number, not '" + e.value() + "'");
    return v;
}

std::optional<int> Cursor::integer(const Entry& e) {
    auto v = elastodyn::parse_number(e.value());
    if (!v || *v != std::floor(*v) || std::fabs(*v) > 1e9) {
        diags_.error(Kind::InvalidValue, e.at(),
                     "'" + e.key + "' must be an integer, not '" + e.value() + "'");
        return std::nullopt;
    }
    return static_cast<int>(*v);
}

std::optional<bool> Cursor::flag(const Entry& e) {
    // Fortran's list-directed read of a LOGICAL: T or F, optionally after a period.
    std::string_view v = e.value();
    if (!v.empty() && v[0] == '.') v.remove_prefix(1);
    if (!v.empty() && (v[0] == 't' || v[0] == 'T')) return true;
    if (!v.empty() && (v[0] == 'f' || v[0] == 'F')) return false;
    diags_.error(Kind::InvalidValue, e.at(),
                 "'" + e.key + "' must be True or False, not '" + e.value() + "'");
    return std::nullopt;
}

std::optional<double> Cursor::number_or_default(const Entry& e, bool& bad) {
    if (is_default(e.value())) return std::nullopt;
    auto v = number(e);
    if (!v) bad = true;
    return v;
}

std::optional<double> Cursor::expect_number(std::string_view key) {
    auto e = expect(key);
    return e ? number(*e) : std::nullopt;
}

std::optional<int> Cursor::expect_integer(std::string_view key) {
    auto e = expect(key);
    return e ? integer(*e) : std::nullopt;
}

std::optional<bool> Cursor::expect_flag(std::string_view key) {
    auto e = expect(key);
    return e ? flag(*e) : std::nullopt;
}

std::optional<std::string> Cursor::expect_text(std::string_view key) {
    auto e = expect(key);
    if (!e) return std::nullopt;
    return e->value();
}

std::optional<int> count(Cursor& c, const Entry& e, int low) {
    auto n = c.integer(e);
    if (!n) return std::nullopt;
    if (*n < low || *n > max_count) {
        c.diags().error(Kind::InvalidValue, e.at(),
                        "'" + e.key + "' must be " + std::to_string(low) + " to " +
                            std::to_string(max_count) + " (it is " + std::to_string(*n) + ")");
        return std::nullopt;
    }
    return n;
}

} // namespace yamsc::aerodyn
