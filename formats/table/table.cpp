// Reading tables of numbers with named columns (table.hpp).
#include "table/table.hpp"

#include "diag/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace yamsc::table {

namespace {

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    const bool delimited = line.find_first_of(",;") != std::string::npos;
    std::string token;
    auto flush = [&] {
        // Trim blanks and quotes around a field.
        auto b = token.find_first_not_of(" \t\r\"");
        auto e = token.find_last_not_of(" \t\r\"");
        out.push_back(b == std::string::npos ? std::string() : token.substr(b, e - b + 1));
        token.clear();
    };
    for (char c : line) {
        if (delimited ? (c == ',' || c == ';') : (c == ' ' || c == '\t')) {
            if (delimited || !token.empty()) flush();
        } else {
            token += c;
        }
    }
    if (delimited || !token.empty()) flush();
    if (!out.empty() && out.back().empty() && delimited && out.size() > 1) out.pop_back();
    return out;
}

bool is_number(const std::string& s, double& value) {
    if (s.empty()) return false;
    std::string text = s;
    for (char& c : text)
        if (c == 'D' || c == 'd') c = 'e'; // Fortran exponents
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end && *end == '\0' && std::isfinite(value);
}

bool numeric_row(const std::vector<std::string>& fields, std::vector<double>& values) {
    values.clear();
    for (const std::string& f : fields) {
        double v = 0;
        if (!is_number(f, v)) return false;
        values.push_back(v);
    }
    return !values.empty();
}

bool units_row(const std::vector<std::string>& fields) {
    return !fields.empty() && std::all_of(fields.begin(), fields.end(), [](const std::string& f) {
        return f.size() >= 2 && f.front() == '(' && f.back() == ')';
    });
}

} // namespace

Table read_table(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw diag::UserError("cannot read '" + path + "'");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    // The header is the last non-numeric row before the first numeric one.
    std::size_t first_data = lines.size();
    std::vector<double> values;
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (numeric_row(split(lines[i]), values)) {
            first_data = i;
            break;
        }
    if (first_data == lines.size() || first_data == 0)
        throw diag::UserError(path + ": no row of column names followed by rows of numbers");
    std::size_t header = first_data - 1;
    std::vector<std::string> units;
    if (units_row(split(lines[header])) && header > 0) {
        units = split(lines[header]);
        --header;
    }
    Table t;
    t.columns = split(lines[header]);
    if (!units.empty() && units.size() == t.columns.size())
        for (std::size_t j = 0; j < units.size(); ++j)
            t.columns[j] += "_[" + units[j].substr(1, units[j].size() - 2) + "]";
    if (t.columns.size() < 2)
        throw diag::UserError(path + ":" + std::to_string(header + 1) +
                              ": expected a time column and at least one channel");
    t.data.assign(t.columns.size(), {});
    for (std::size_t i = first_data; i < lines.size(); ++i) {
        const auto fields = split(lines[i]);
        if (fields.empty()) continue;
        if (!numeric_row(fields, values) || values.size() != t.columns.size())
            throw diag::UserError(path + ":" + std::to_string(i + 1) + ": expected " +
                                  std::to_string(t.columns.size()) + " numbers");
        if (!t.data[0].empty() && !(values[0] > t.data[0].back()))
            throw diag::UserError(path + ":" + std::to_string(i + 1) + ": time does not rise");
        for (std::size_t j = 0; j < values.size(); ++j) t.data[j].push_back(values[j]);
    }
    return t;
}

} // namespace yamsc::table
