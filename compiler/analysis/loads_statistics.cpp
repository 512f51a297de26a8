// Statistics of a channel (loads_statistics.hpp).
#include "analysis/loads_statistics.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::analysis {

ChannelStatistics channel_statistics(const std::vector<double>& y) {
    ChannelStatistics s;
    const auto [lo, hi] = std::minmax_element(y.begin(), y.end());
    s.min = *lo;
    s.max = *hi;
    const double n = static_cast<double>(y.size());
    double sum = 0;
    for (double v : y) sum += v;
    s.mean = sum / n;
    if (s.min == s.max) {
        s.mean = s.min; // exact for a constant channel
        return s;
    }
    // Two passes: moments about the mean, not sums of powers (which cancel).
    double m2 = 0, m3 = 0, m4 = 0;
    for (double v : y) {
        const double d = v - s.mean, d2 = d * d;
        m2 += d2;
        m3 += d2 * d;
        m4 += d2 * d2;
    }
    m2 /= n;
    m3 /= n;
    m4 /= n;
    s.std_dev = std::sqrt(m2);
    s.skewness = m3 / (m2 * s.std_dev);
    s.kurtosis = m4 / (m2 * m2);
    return s;
}

} // namespace yamsc::analysis
