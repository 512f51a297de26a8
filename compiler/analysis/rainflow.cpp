// Rainflow counting and damage-equivalent loads (rainflow.hpp).
#include "analysis/rainflow.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::analysis {

namespace {

int sign(double v) {
    return (v > 0) - (v < 0);
}

/// NumPy's pairwise summation (its `sum` of a float64 array), so that a DEL summed
/// over bins rounds as openfast_toolbox's does.
double pairwise_sum(const double* a, std::size_t n) {
    if (n < 8) {
        double s = 0;
        for (std::size_t i = 0; i < n; ++i) s += a[i];
        return s;
    }
    if (n <= 128) {
        double r[8];
        for (int k = 0; k < 8; ++k) r[k] = a[k];
        std::size_t i = 8;
        for (; i < n - n % 8; i += 8)
            for (int k = 0; k < 8; ++k) r[k] += a[i + static_cast<std::size_t>(k)];
        double s = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]));
        for (; i < n; ++i) s += a[i];
        return s;
    }
    std::size_t half = n / 2;
    half -= half % 8;
    return pairwise_sum(a, half) + pairwise_sum(a + half, n - half);
}

/// The range of each half cycle, a full cycle being two (the order NumPy's
/// histogram sums them in).
std::vector<double> half_cycle_ranges(const std::vector<Cycle>& cycles) {
    std::vector<double> ranges;
    for (const Cycle& c : cycles) {
        ranges.push_back(c.range);
        if (c.count == 1.0) ranges.push_back(c.range);
    }
    return ranges;
}

} // namespace

std::vector<double> turning_points(const std::vector<double>& y) {
    const std::size_t n = y.size();
    if (n < 2) return y;
    std::vector<int> slope(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) slope[i] = sign(y[i + 1] - y[i]);
    // A plateau takes the slope before it; leading plateaus the first slope after.
    std::size_t first = 0;
    while (first < slope.size() && slope[first] == 0) ++first;
    if (first == slope.size()) return {y.front()};
    slope[0] = slope[first];
    for (std::size_t i = 1; i < slope.size(); ++i)
        if (slope[i] == 0) slope[i] = slope[i - 1];
    std::vector<double> points{y.front()};
    for (std::size_t i = 1; i + 1 < n; ++i)
        if (slope[i] * slope[i - 1] < 0) points.push_back(y[i]);
    points.push_back(y.back());
    return points;
}

std::vector<Cycle> rainflow(const std::vector<double>& y) {
    std::vector<Cycle> cycles;
    std::vector<double> stack;
    auto cycle = [&](double a, double b, double count) {
        const double range = std::abs(a - b);
        if (range > 0) cycles.push_back({range, (a + b) / 2, count});
    };
    for (double point : turning_points(y)) {
        stack.push_back(point);
        // X: the latest range; Y: the one before it.
        while (stack.size() > 2) {
            const std::size_t k = stack.size();
            const double y_range = std::abs(stack[k - 3] - stack[k - 2]);
            const double x_range = std::abs(stack[k - 2] - stack[k - 1]);
            if (x_range < y_range) break;
            if (k == 3) { // Y holds the starting point: a half cycle, the start dropped
                cycle(stack[0], stack[1], 0.5);
                stack.erase(stack.begin());
            } else {
                cycle(stack[k - 3], stack[k - 2], 1.0);
                stack.erase(stack.end() - 3, stack.end() - 1);
            }
        }
    }
    for (std::size_t i = 0; i + 1 < stack.size(); ++i) cycle(stack[i], stack[i + 1], 0.5);
    return cycles;
}

double equivalent_load(const std::vector<Cycle>& cycles, double m, double duration,
                       const EquivalentLoadOptions& options) {
    if (cycles.empty()) return 0;
    const double equivalent_cycles = duration * options.frequency;
    std::vector<double> terms;
    if (options.bins <= 0) {
        for (const Cycle& c : cycles)
            terms.push_back(std::pow(c.range, m) * c.count / equivalent_cycles);
        return std::pow(pairwise_sum(terms.data(), terms.size()), 1.0 / m);
    }
    const std::vector<double> ranges = half_cycle_ranges(cycles);
    const auto [min_it, max_it] = std::minmax_element(ranges.begin(), ranges.end());
    double lo = *min_it, hi = *max_it;
    if (lo == hi) {
        lo -= 0.5;
        hi += 0.5;
    }
    const auto bins = static_cast<std::size_t>(options.bins);
    // numpy.linspace(lo, hi, bins + 1): k * step + lo, the last edge hi itself.
    std::vector<double> edges(bins + 1);
    const double step = (hi - lo) / static_cast<double>(bins);
    for (std::size_t k = 0; k < bins; ++k) {
        double e = static_cast<double>(k) * step;
        e += lo;
        edges[k] = e;
    }
    edges[bins] = hi;
    std::vector<double> sum(bins, 0.0), count(bins, 0.0);
    for (double r : ranges) {
        // numpy.histogram: [e_k, e_k+1), the last bin closed.
        auto k = static_cast<std::size_t>(std::upper_bound(edges.begin(), edges.end(), r) -
                                          edges.begin());
        k = std::min(k, bins) - 1;
        sum[k] += r;
        count[k] += 1;
    }
    terms.assign(bins, 0.0);
    for (std::size_t k = 0; k < bins; ++k)
        if (count[k] > 0) {
            const double mean_range = sum[k] / count[k];
            terms[k] = std::pow(mean_range, m) * (count[k] / 2) / equivalent_cycles;
        }
    return std::pow(pairwise_sum(terms.data(), bins), 1.0 / m);
}

} // namespace yamsc::analysis
