// Lifetime DELs weighted by the wind speed distribution (loads_lifetime.hpp).
#include "analysis/loads_lifetime.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::analysis {

double Weibull::cdf(double v) const {
    return v <= 0 ? 0.0 : 1.0 - std::exp(-std::pow(v / scale, shape));
}

Weibull iec_weibull(WindClass c) {
    const double v_ref = c == WindClass::I ? 50.0 : c == WindClass::II ? 42.5 : 37.5;
    const double v_ave = 0.2 * v_ref;
    return {2.0 * v_ave / std::sqrt(M_PI), 2.0};
}

std::vector<double> run_probabilities(const std::vector<double>& speeds, const Weibull& w) {
    std::vector<double> distinct = speeds;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    const std::size_t n = distinct.size();
    std::vector<double> bin_probability(n);
    for (std::size_t j = 0; j < n; ++j) {
        // A speed alone: a bin 1 m/s wide (no neighbour gives a width).
        const double below = j > 0   ? distinct[j] - distinct[j - 1]
                             : n > 1 ? distinct[1] - distinct[0]
                                     : 1.0;
        const double above = j + 1 < n ? distinct[j + 1] - distinct[j] : below;
        bin_probability[j] = w.cdf(distinct[j] + above / 2) - w.cdf(distinct[j] - below / 2);
    }
    std::vector<double> p(speeds.size());
    for (std::size_t i = 0; i < speeds.size(); ++i) {
        const auto j = static_cast<std::size_t>(
            std::lower_bound(distinct.begin(), distinct.end(), speeds[i]) - distinct.begin());
        const auto runs = std::count(speeds.begin(), speeds.end(), speeds[i]);
        p[i] = bin_probability[j] / static_cast<double>(runs);
    }
    return p;
}

double lifetime_equivalent_load(const std::vector<double>& dels,
                                const std::vector<double>& probabilities, double m,
                                double life_seconds, double frequency, double life_cycles) {
    const double n_life = life_cycles > 0 ? life_cycles : frequency * life_seconds;
    double damage = 0;
    for (std::size_t i = 0; i < dels.size(); ++i)
        damage += probabilities[i] * life_seconds * frequency * std::pow(dels[i], m);
    return std::pow(damage / n_life, 1.0 / m);
}

} // namespace yamsc::analysis
