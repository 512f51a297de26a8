#include "performance_table/performance_table.hpp"

#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>

namespace yamsc::performance_table {
namespace {

/// The numbers of the next non-empty, non-comment line; empty at the end.
std::vector<double> next_row(std::istream& in, const std::string& source, int& line_no) {
    std::string line;
    while (std::getline(in, line)) {
        ++line_no;
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        std::istringstream s(line);
        s.imbue(std::locale::classic());
        std::vector<double> row;
        double v = 0;
        while (s >> v) row.push_back(v);
        if (!s.eof())
            throw std::runtime_error(source + ":" + std::to_string(line_no) +
                                     ": expected numbers only");
        return row;
    }
    return {};
}

void check_increasing(const std::vector<double>& v, const std::string& what,
                      const std::string& source) {
    if (v.size() < 2)
        throw std::runtime_error(source + ": the " + what + " needs 2 entries or more");
    for (std::size_t i = 1; i < v.size(); ++i)
        if (!(v[i] > v[i - 1]))
            throw std::runtime_error(source + ": the " + what + " is not increasing");
}

} // namespace

Table read_performance_table(std::istream& in, const std::string& source) {
    Table t;
    int line_no = 0;
    t.pitch_deg = next_row(in, source, line_no);
    t.tsr = next_row(in, source, line_no);
    next_row(in, source, line_no); // the wind speed vector: the table is for any speed
    check_increasing(t.pitch_deg, "pitch vector", source);
    check_increasing(t.tsr, "TSR vector", source);
    for (std::vector<double>* m : {&t.cp, &t.ct, &t.cq}) {
        for (std::size_t r = 0; r < t.tsr.size(); ++r) {
            const std::vector<double> row = next_row(in, source, line_no);
            if (row.size() != t.pitch_deg.size())
                throw std::runtime_error(source + ":" + std::to_string(line_no) + ": " +
                                         std::to_string(row.size()) + " values, expected " +
                                         std::to_string(t.pitch_deg.size()) +
                                         " (one per pitch angle)");
            for (double v : row)
                if (!std::isfinite(v))
                    throw std::runtime_error(source + ":" + std::to_string(line_no) +
                                             ": a value is not finite");
            m->insert(m->end(), row.begin(), row.end());
        }
    }
    return t;
}

} // namespace yamsc::performance_table
