#include "yamsc/performance_table.hpp"

#include "performance_table/performance_table.hpp"

#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace yamsc::runtime {
namespace {

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
    performance_table::Table t = performance_table::read_performance_table(in, source);
    return {std::move(t.pitch_deg), std::move(t.tsr), std::move(t.cp), std::move(t.ct),
            std::move(t.cq)};
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
