#include "elastodyn/file.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace yamsc::elastodyn {

bool same_key(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

namespace {

bool is_separator(const std::string& token) {
    return token.size() >= 3 &&
           (token.compare(0, 3, "---") == 0 || token.compare(0, 3, "===") == 0);
}

} // namespace

std::vector<Token> tokenize(std::string_view line) {
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < line.size()) {
        if (std::isspace(static_cast<unsigned char>(line[i])) || line[i] == ',') {
            ++i;
            continue;
        }
        Token t;
        t.col = static_cast<int>(i) + 1;
        if (line[i] == '"' || line[i] == '\'') {
            const char quote = line[i++];
            const std::size_t end = std::min(line.find(quote, i), line.size());
            t.text = std::string(line.substr(i, end - i));
            t.quoted = true;
            i = end + 1;
        } else {
            const std::size_t begin = i;
            while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])) &&
                   line[i] != ',')
                ++i;
            t.text = std::string(line.substr(begin, i - begin));
        }
        out.push_back(std::move(t));
    }
    return out;
}

std::optional<double> parse_number(std::string_view token) {
    std::string text(token);
    for (char& c : text)
        if (c == 'd' || c == 'D') c = 'e'; // Fortran double-precision exponent
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

int EdTable::column(std::string_view name) const {
    for (std::size_t i = 0; i < columns.size(); ++i)
        if (same_key(columns[i], name)) return static_cast<int>(i);
    return -1;
}

ElastoDynFile::ElastoDynFile(std::shared_ptr<const diag::SourceFile> file)
    : file_(std::move(file)) {
    for (int line = 1; line <= file_->line_count(); ++line) {
        const std::vector<Token> t = tokenize(file_->line(line));
        if (t.size() < 2 || is_separator(t[0].text)) continue;
        if (!std::isalpha(static_cast<unsigned char>(t[1].text[0]))) continue; // a table row
        entries_.push_back({t[1].text, t[0].text, line, t[0].col});
    }
}

const ElastoDynFile::Entry* ElastoDynFile::find(std::string_view key) const {
    for (const Entry& e : entries_)
        if (same_key(e.key, key)) return &e;
    return nullptr;
}

diag::Location ElastoDynFile::location(std::string_view key) const {
    const Entry* e = find(key);
    return e ? diag::Location{file_, e->line, e->col} : diag::Location{file_, 0, 0};
}

void ElastoDynFile::missing(std::string_view key, diag::Diagnostics& diags) const {
    diags.error(diag::Kind::MissingProperty, {file_, 0, 0},
                "the ElastoDyn file has no value for '" + std::string(key) + "'");
}

std::optional<std::string> ElastoDynFile::get_string(std::string_view key,
                                                     diag::Diagnostics& diags) const {
    const Entry* e = find(key);
    if (!e) {
        missing(key, diags);
        return std::nullopt;
    }
    return e->value;
}

std::optional<double> ElastoDynFile::get_double(std::string_view key,
                                                diag::Diagnostics& diags) const {
    const Entry* e = find(key);
    if (!e) {
        missing(key, diags);
        return std::nullopt;
    }
    auto v = parse_number(e->value);
    if (!v)
        diags.error(diag::Kind::InvalidValue, location(key),
                    "'" + std::string(key) + "' must be a number, not '" + e->value + "'");
    return v;
}

std::optional<int> ElastoDynFile::get_int(std::string_view key, diag::Diagnostics& diags) const {
    auto v = get_double(key, diags);
    if (!v) return std::nullopt;
    if (*v != std::floor(*v) || std::fabs(*v) > 1e9) {
        diags.error(diag::Kind::InvalidValue, location(key),
                    "'" + std::string(key) + "' must be an integer");
        return std::nullopt;
    }
    return static_cast<int>(*v);
}

std::optional<bool> ElastoDynFile::get_bool(std::string_view key, diag::Diagnostics& diags) const {
    auto text = get_string(key, diags);
    if (!text) return std::nullopt;
    for (const char* yes : {"true", "t", ".true."})
        if (same_key(*text, yes)) return true;
    for (const char* no : {"false", "f", ".false."})
        if (same_key(*text, no)) return false;
    diags.error(diag::Kind::InvalidValue, location(key),
                "'" + std::string(key) + "' must be True or False, not '" + *text + "'");
    return std::nullopt;
}

std::optional<EdTable> ElastoDynFile::get_table(std::string_view first_column, int rows,
                                                diag::Diagnostics& diags) const {
    const std::string name(first_column);
    int line = 1;
    std::vector<Token> header;
    for (; line <= file_->line_count(); ++line) {
        header = tokenize(file_->line(line));
        if (!header.empty() && same_key(header[0].text, first_column)) break;
    }
    if (line > file_->line_count()) {
        diags.error(diag::Kind::MissingProperty, {file_, 0, 0},
                    "the ElastoDyn file has no table with the column '" + name + "'");
        return std::nullopt;
    }
    EdTable table;
    for (const Token& t : header) table.columns.push_back(t.text);
    table.header_line = line;
    ++line;
    if (file_->line(line).find_first_not_of(" \t") != std::string_view::npos &&
        file_->line(line)[file_->line(line).find_first_not_of(" \t")] == '(')
        ++line; // the units row
    const std::size_t ncol = table.columns.size();
    for (int r = 0; r < rows; ++r, ++line) {
        const std::vector<Token> t = tokenize(file_->line(line));
        if (t.empty() || !parse_number(t[0].text)) {
            diags.error(diag::Kind::InvalidValue, {file_, line, 1},
                        "the table '" + name + "' has " + std::to_string(r) + " rows, expected " +
                            std::to_string(rows));
            return std::nullopt;
        }
        if (t.size() < ncol) {
            diags.error(diag::Kind::InvalidValue, {file_, line, t.back().col},
                        "this row of the table '" + name + "' has " + std::to_string(t.size()) +
                            " values, expected " + std::to_string(ncol));
            return std::nullopt;
        }
        std::vector<double> values;
        for (std::size_t c = 0; c < ncol; ++c) {
            auto v = parse_number(t[c].text);
            if (!v) {
                diags.error(diag::Kind::InvalidValue, {file_, line, t[c].col},
                            "'" + t[c].text + "' in column '" + table.columns[c] +
                                "' is not a number");
                return std::nullopt;
            }
            values.push_back(*v);
        }
        table.rows.push_back(std::move(values));
        table.lines.push_back(line);
    }
    const std::vector<Token> after = tokenize(file_->line(line));
    if (!after.empty() && parse_number(after[0].text)) {
        diags.error(diag::Kind::InvalidValue, {file_, line, 1},
                    "the table '" + name + "' has more than the " + std::to_string(rows) +
                        " rows announced");
        return std::nullopt;
    }
    return table;
}

} // namespace yamsc::elastodyn
