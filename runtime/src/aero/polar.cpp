#include "yamsc/aero/polar.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::aero {

namespace {

double wrap_to_pi(double a) {
    constexpr double pi = 3.14159265358979323846;
    a += pi;
    if (a >= 0 && a < 2 * pi) return a - pi; // fmod would return a itself
    a = std::fmod(a, 2 * pi);
    if (a < 0) a += 2 * pi;
    return a - pi;
}

// The table's coefficients in segment i at the wrapped, clamped angle a.
Coefficients interpolate(const PolarTable& table, std::size_t i, double a) {
    const auto& x = table.alpha;
    const double w = (a - x[i]) / (x[i + 1] - x[i]);
    auto at = [&](const std::vector<double>& v) { return v[i] + w * (v[i + 1] - v[i]); };
    return {at(table.cl), at(table.cd), table.cm.empty() ? 0.0 : at(table.cm)};
}

Coefficients constant(const PolarTable& table) {
    return {table.cl[0], table.cd[0], table.cm.empty() ? 0.0 : table.cm[0]};
}

} // namespace

Coefficients lookup(const PolarTable& table, double alpha) {
    const auto& x = table.alpha;
    if (x.size() == 1) return constant(table);
    const double a = std::clamp(wrap_to_pi(alpha), x.front(), x.back());
    // The segment [x[i], x[i+1]] holding a (the last one for a == x.back()).
    const std::size_t i =
        std::min<std::size_t>(std::upper_bound(x.begin(), x.end(), a) - x.begin(), x.size() - 1) -
        1;
    return interpolate(table, i, a);
}

SegmentIndex::SegmentIndex(const std::vector<double>& x) {
    // About four buckets per row: a bucket's first row is then one or two rows
    // from the answer.
    const std::size_t buckets = 4 * x.size();
    x0_ = x.front();
    const double range = x.back() - x.front();
    inverse_width_ = range > 0 ? static_cast<double>(buckets) / range : 0.0;
    first_.resize(buckets);
    std::size_t i = 0;
    for (std::size_t b = 0; b < buckets; ++b) {
        const double edge = x0_ + static_cast<double>(b) / inverse_width_;
        while (i + 1 < x.size() && x[i + 1] <= edge) ++i;
        first_[b] = i;
    }
}

std::size_t SegmentIndex::segment(const std::vector<double>& x, double a) const {
    const std::size_t n = x.size();
    if (std::isnan(a)) return n - 2; // upper_bound finds no row above NaN
    const double position = (a - x0_) * inverse_width_;
    const std::size_t b =
        position > 0 ? std::min(static_cast<std::size_t>(position), first_.size() - 1) : 0;
    // The bucket's row is a guess: the last row at or below a is found from it.
    std::size_t i = first_[b];
    while (i > 0 && x[i] > a) --i;
    while (i + 1 < n && x[i + 1] <= a) ++i;
    return std::min(i, n - 2);
}

IndexedPolar::IndexedPolar(const PolarTable& table) : table_(&table) {
    if (table.alpha.size() > 1) index_ = SegmentIndex(table.alpha);
}

Coefficients IndexedPolar::at(double alpha) const {
    const auto& x = table_->alpha;
    if (x.size() == 1) return constant(*table_);
    const double a = std::clamp(wrap_to_pi(alpha), x.front(), x.back());
    return interpolate(*table_, index_.segment(x, a), a);
}

} // namespace yamsc::aero
