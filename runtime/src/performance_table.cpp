#include "yamsc/performance_table.hpp"

#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace yamsc::runtime {
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

// The interpolation weights, shared word for word with the C file of
// `yamsc rotor-table` (hermite_weights.inc).
#define PFX_add_slope hermite_add_slope
#define PFX_weights hermite_weights_of
#include "hermite_weights.inc"
#undef PFX_add_slope
#undef PFX_weights

void hermite_weights(const std::vector<double>& xs, double x, int order, std::vector<double>& w) {
    w.assign(xs.size(), 0.0);
    hermite_weights_of(xs.data(), xs.size(), x, order, w.data());
}

} // namespace

PerformanceTable read_performance_table(std::istream& in, const std::string& source) {
    PerformanceTable t;
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

PerformanceTable read_performance_table(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open the performance table '" + path + "'");
    return read_performance_table(in, path);
}

Coefficient interpolate(const PerformanceTable& table, const std::vector<double>& values,
                        double tsr, double pitch_deg) {
    if (values.size() != table.tsr.size() * table.pitch_deg.size())
        throw std::invalid_argument("interpolate: the values do not match the table's size");
    std::vector<double> wt0, wt1, wp0, wp1;
    hermite_weights(table.tsr, tsr, 0, wt0);
    hermite_weights(table.tsr, tsr, 1, wt1);
    hermite_weights(table.pitch_deg, pitch_deg, 0, wp0);
    hermite_weights(table.pitch_deg, pitch_deg, 1, wp1);
    Coefficient c;
    const std::size_t np = table.pitch_deg.size();
    for (std::size_t r = 0; r < table.tsr.size(); ++r) {
        if (wt0[r] == 0.0 && wt1[r] == 0.0) continue;
        double v0 = 0, v1 = 0;
        for (std::size_t k = 0; k < np; ++k) {
            v0 += wp0[k] * values[r * np + k];
            v1 += wp1[k] * values[r * np + k];
        }
        c.value += wt0[r] * v0;
        c.d_tsr += wt1[r] * v0;
        c.d_pitch += wt0[r] * v1;
    }
    return c;
}

} // namespace yamsc::runtime
