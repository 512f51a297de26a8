#pragma once
// The measure of a run against OpenFAST's: ε = mean |y - ref| / (max ref -
// min ref); for a constant reference (a cylinder node's zero induction) the
// largest difference.
#include <algorithm>
#include <cmath>
#include <vector>

namespace aero_test {

inline double epsilon(const std::vector<double>& y, const std::vector<double>& ref) {
    double sum = 0, worst = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        sum += std::abs(y[i] - ref[i]);
        worst = std::max(worst, std::abs(y[i] - ref[i]));
    }
    const auto [lo, hi] = std::minmax_element(ref.begin(), ref.end());
    return *hi > *lo ? sum / double(ref.size()) / (*hi - *lo) : worst;
}

} // namespace aero_test
