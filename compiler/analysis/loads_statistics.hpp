#pragma once
// The statistics of one channel over a window, as pCrunch's AeroelasticOutput
// defines them: central moments m_k = mean((y - mean)^k) (no bias correction),
// standard deviation sqrt(m2), skewness m3 / m2^1.5, kurtosis m4 / m2^2 (Pearson's,
// 3 for a normal distribution, not the excess). A constant channel has a standard
// deviation, skewness and kurtosis of 0.
#include <vector>

namespace yamsc::analysis {

struct ChannelStatistics {
    double mean = 0, std_dev = 0, min = 0, max = 0, skewness = 0, kurtosis = 0;
};

/// `y` must not be empty.
ChannelStatistics channel_statistics(const std::vector<double>& y);

} // namespace yamsc::analysis
