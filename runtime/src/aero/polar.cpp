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

} // namespace

Coefficients lookup(const PolarTable& table, double alpha) {
    const auto& x = table.alpha;
    const bool has_cm = !table.cm.empty();
    if (x.size() == 1) return {table.cl[0], table.cd[0], has_cm ? table.cm[0] : 0.0};
    const double a = std::clamp(wrap_to_pi(alpha), x.front(), x.back());
    // The segment [x[i], x[i+1]] holding a (the last one for a == x.back()).
    const std::size_t i =
        std::min<std::size_t>(std::upper_bound(x.begin(), x.end(), a) - x.begin(), x.size() - 1) -
        1;
    const double w = (a - x[i]) / (x[i + 1] - x[i]);
    auto at = [&](const std::vector<double>& v) { return v[i] + w * (v[i + 1] - v[i]); };
    return {at(table.cl), at(table.cd), has_cm ? at(table.cm) : 0.0};
}

} // namespace yamsc::aero
