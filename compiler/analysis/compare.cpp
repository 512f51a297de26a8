// Reading reference time series and scoring a simulation against them.
#include "analysis/compare.hpp"

#include "driver/bindings.hpp"
#include "table/table.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace yamsc::analysis {

using diag::UserError;

Table read_table(const std::string& path) {
    table::Table t = table::read_table(path);
    return {std::move(t.columns), std::move(t.data)};
}

std::vector<double> unwrap(std::vector<double> values, double period) {
    double shift = 0;
    for (std::size_t i = 1; i < values.size(); ++i) {
        const double raw_step = values[i] + shift - values[i - 1];
        if (raw_step > period / 2) shift -= period;
        if (raw_step < -period / 2) shift += period;
        values[i] += shift;
    }
    return values;
}

double interpolate(const std::vector<double>& t, const std::vector<double>& y, double at) {
    if (t.empty()) return 0;
    if (at <= t.front()) return y.front();
    if (at >= t.back()) return y.back();
    const auto hi = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin());
    const std::size_t lo = hi - 1;
    const double w = (at - t[lo]) / (t[hi] - t[lo]);
    return y[lo] + w * (y[hi] - y[lo]);
}

Comparison compare_tables(const Table& simulation, const Table& reference) {
    Comparison c;
    if (simulation.rows() == 0 || reference.rows() == 0)
        throw UserError("nothing to compare: a table has no rows");
    const std::vector<double>& ts = simulation.data.front();
    const std::vector<double>& tr = reference.data.front();
    // Tolerate the rounding of times written with few digits.
    const double eps = 1e-9 * std::max(1.0, std::abs(tr.back()));
    c.t_begin = std::max(ts.front(), tr.front());
    c.t_end = std::min(ts.back(), tr.back());
    if (!(c.t_end > c.t_begin))
        throw UserError("the simulation and the reference do not overlap in time");
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < tr.size(); ++i)
        if (tr[i] >= c.t_begin - eps && tr[i] <= c.t_end + eps) rows.push_back(i);
    for (std::size_t j = 1; j < reference.columns.size(); ++j) {
        const std::string& name = reference.columns[j];
        int found = simulation.find(name);
        for (std::size_t k = 1; found < 0 && k < simulation.columns.size(); ++k)
            if (base_name(simulation.columns[k]) == base_name(name)) found = static_cast<int>(k);
        if (found < 1) {
            c.missing.push_back(name);
            continue;
        }
        std::vector<double> ys = simulation.data[static_cast<std::size_t>(found)];
        std::vector<double> yr = reference.data[j];
        if (base_name(name) == "Azimuth") {
            ys = unwrap(ys, 360.0);
            yr = unwrap(yr, 360.0);
        }
        ChannelScore s;
        s.name = name;
        s.matched = simulation.columns[static_cast<std::size_t>(found)];
        s.samples = rows.size();
        double lo = INFINITY, hi = -INFINITY, mean = 0;
        for (std::size_t i : rows) {
            lo = std::min(lo, yr[i]);
            hi = std::max(hi, yr[i]);
            mean += yr[i];
        }
        mean /= static_cast<double>(rows.size());
        s.range = hi - lo;
        double abs_sum = 0, sq_err = 0, sq_dev = 0;
        for (std::size_t i : rows) {
            const double e = interpolate(ts, ys, tr[i]) - yr[i];
            abs_sum += std::abs(e);
            s.max_abs_error = std::max(s.max_abs_error, std::abs(e));
            sq_err += e * e;
            sq_dev += (yr[i] - mean) * (yr[i] - mean);
        }
        const double n = static_cast<double>(rows.size());
        s.mean_rel_error = s.range > 0 ? abs_sum / n / s.range : (abs_sum > 0 ? INFINITY : 0.0);
        s.r2 = sq_dev > 0 ? 1.0 - sq_err / sq_dev : (sq_err > 0 ? -INFINITY : 1.0);
        c.channels.push_back(s);
    }
    return c;
}

std::string format_comparison(const Comparison& c, const std::string& reference_name) {
    std::ostringstream out;
    char line[256];
    std::size_t width = 7;
    for (const ChannelScore& s : c.channels) width = std::max(width, s.name.size());
    std::snprintf(line, sizeof line, "compared with %s over t = %g .. %g s\n",
                  reference_name.c_str(), c.t_begin, c.t_end);
    out << line;
    std::snprintf(line, sizeof line, "%-*s  %17s  %15s  %10s  %8s\n", static_cast<int>(width),
                  "channel", "mean rel. error", "max abs. error", "R^2", "samples");
    out << line;
    for (const ChannelScore& s : c.channels) {
        std::snprintf(line, sizeof line, "%-*s  %15.3f %%  %15.4g  %10.6f  %8zu\n",
                      static_cast<int>(width), s.name.c_str(), 100.0 * s.mean_rel_error,
                      s.max_abs_error, s.r2, s.samples);
        out << line;
    }
    for (const std::string& m : c.missing) out << m << ": not in the simulation\n";
    out << "(mean rel. error: mean |sim - ref| / (max ref - min ref))\n";
    return out.str();
}

} // namespace yamsc::analysis
