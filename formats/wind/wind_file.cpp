#include "wind/wind_file.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yamsc::wind {

namespace {

struct Field {
    std::string text;
    int column = 0; // 1-based
};

/// The fields of a line split at whitespace (and commas in a CSV), with their columns.
std::vector<Field> split(const std::string& line, bool csv) {
    std::vector<Field> fields;
    std::size_t i = 0;
    auto separator = [&](char c) {
        return c == ' ' || c == '\t' || c == '\r' || (csv && c == ',');
    };
    while (i < line.size()) {
        while (i < line.size() && separator(line[i])) ++i;
        if (i >= line.size()) break;
        const std::size_t start = i;
        while (i < line.size() && !separator(line[i])) ++i;
        fields.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return fields;
}

bool number(const std::string& text, double& value) {
    std::istringstream s(text);
    s.imbue(std::locale::classic());
    s >> value;
    return !s.fail() && s.eof() && std::isfinite(value);
}

[[noreturn]] void fail(const std::string& source, int line, int column, const std::string& what) {
    throw std::runtime_error(source + ":" + std::to_string(line) + ":" + std::to_string(column) +
                             ": " + what);
}

} // namespace

Samples read_wind_file(std::istream& in, const std::string& source) {
    Samples w;
    std::vector<double>* columns[max_columns] = {&w.time,
                                                 &w.speed,
                                                 &w.direction,
                                                 &w.vertical,
                                                 &w.horizontal_shear,
                                                 &w.power_law,
                                                 &w.linear_vertical_shear,
                                                 &w.gust,
                                                 &w.upflow};
    std::string line;
    int line_no = 0;
    bool csv = false;
    while (std::getline(in, line)) {
        ++line_no;
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#' || line[first] == '!') continue;
        if (w.time.empty()) csv = line.find(',') != std::string::npos;
        const std::vector<Field> fields = split(line, csv);
        double values[max_columns] = {};
        int read = 0;
        const int wanted = w.time.empty() ? (csv ? 2 : max_columns) : w.columns;
        for (; read < wanted && read < static_cast<int>(fields.size()); ++read)
            if (!number(fields[static_cast<std::size_t>(read)].text, values[read])) break;
        if (w.time.empty()) {
            if (read < 2) {
                if (line_no == 1) continue; // the header
                fail(source, line_no,
                     read < static_cast<int>(fields.size())
                         ? fields[static_cast<std::size_t>(read)].column
                         : static_cast<int>(first) + 1,
                     "expected time and wind speed");
            }
            w.columns = read;
        } else if (read < w.columns) {
            const int column = read < static_cast<int>(fields.size())
                                   ? fields[static_cast<std::size_t>(read)].column
                                   : static_cast<int>(line.find_last_not_of(" \t\r")) + 2;
            fail(source, line_no, column,
                 "expected " + std::to_string(w.columns) +
                     " numbers, as in the first row (time, wind speed, ...)");
        }
        if (!w.time.empty() && !(values[0] > w.time.back()))
            fail(source, line_no, fields.front().column, "times must increase");
        for (int c = 0; c < max_columns; ++c) columns[c]->push_back(values[c]);
    }
    if (w.time.empty()) throw std::runtime_error(source + ": no wind samples");
    return w;
}

} // namespace yamsc::wind
