// Rainflow counting against ASTM E1049-85's worked example, and DELs and
// statistics against closed forms.
#include "analysis/loads_lifetime.hpp"
#include "analysis/loads_statistics.hpp"
#include "analysis/rainflow.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <map>

using namespace yamsc::analysis;

namespace {

/// Cycle counts by range.
std::map<double, double> counts_by_range(const std::vector<Cycle>& cycles) {
    std::map<double, double> counts;
    for (const Cycle& c : cycles) counts[c.range] += c.count;
    return counts;
}

} // namespace

TEST_CASE("rainflow: ASTM E1049-85, 5.4.4 and its Fig. 6 (the series counted by hand)") {
    // Points A..I of the standard's example; its table of cycles: range 3: 0.5,
    // 4: 1.5, 6: 0.5, 8: 1.0, 9: 0.5.
    const std::vector<double> y = {-2, 1, -3, 5, -1, 3, -4, 4, -2};
    const std::map<double, double> expected = {{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
    CHECK(counts_by_range(rainflow(y)) == expected);
    // Samples between the turning points and plateaus change nothing.
    const std::vector<double> dense = {-2, 0, 1, 1, 0, -3, 0, 5, -1, -1, 0, 3, 0, -4, 0, 4, 0, -2};
    CHECK(counts_by_range(rainflow(dense)) == expected);
    // The cycles as the procedure finds them: the full cycle E-F (range 4) with mean 1.
    bool found = false;
    for (const Cycle& c : rainflow(y))
        if (c.count == 1.0 && c.range == 4) found = c.mean == 1.0;
    CHECK(found);
}

TEST_CASE("turning points: first and last samples kept, plateaus take the slope before them") {
    CHECK(turning_points({1, 1, 2, 2, 3, 1, 1, 0, 5}) == std::vector<double>{1, 3, 0, 5});
    CHECK(turning_points({2, 2, 2}) == std::vector<double>{2});
    CHECK(rainflow({2, 2, 2}).empty());
    CHECK(equivalent_load(rainflow({2, 2, 2}), 4, 10, {}) == 0.0);
}

TEST_CASE("DEL of a cosine: N cycles of range 2A over T give 2A (N / (f_eq T))^(1/m)") {
    const double amplitude = 3.5, period = 2.0;
    const int cycles = 25, per_period = 40;
    std::vector<double> y;
    for (int i = 0; i <= cycles * per_period; ++i)
        y.push_back(amplitude * std::cos(2 * M_PI * i / per_period));
    const double duration = cycles * period;
    const auto counted = rainflow(y);
    double total = 0;
    for (const Cycle& c : counted) {
        CHECK(c.range == doctest::Approx(2 * amplitude).epsilon(1e-14));
        total += c.count;
    }
    CHECK(total == cycles);
    for (double m : {1.0, 4.0, 10.0})
        for (int bins : {0, 100}) {
            for (double f : {1.0, 0.5}) {
                const double expected = 2 * amplitude * std::pow(cycles / (f * duration), 1 / m);
                CHECK(equivalent_load(counted, m, duration, {f, bins}) ==
                      doctest::Approx(expected).epsilon(1e-12));
            }
        }
}

TEST_CASE("DEL with bins: each bin at the mean of its ranges, as openfast_toolbox") {
    // Half cycles of ranges 1 and 3 and a full cycle of 2.9: with 2 bins over
    // [1, 3] (edges 1, 2, 3) the bins hold {1} and {2.9, 2.9, 3}.
    const std::vector<Cycle> cycles = {{1, 0, 0.5}, {2.9, 0, 1.0}, {3, 0, 0.5}};
    const double m = 4, duration = 10;
    const double binned =
        std::pow((0.5 * 1 + 1.5 * std::pow((2.9 * 2 + 3) / 3, m)) / duration, 1 / m);
    CHECK(equivalent_load(cycles, m, duration, {1.0, 2}) == doctest::Approx(binned).epsilon(1e-15));
    const double exact =
        std::pow((0.5 + std::pow(2.9, m) + 0.5 * std::pow(3, m)) / duration, 1 / m);
    CHECK(equivalent_load(cycles, m, duration, {1.0, 0}) == doctest::Approx(exact).epsilon(1e-15));
}

TEST_CASE("statistics: central moments without bias correction, Pearson's kurtosis") {
    const ChannelStatistics s = channel_statistics({1, 2, 3, 4});
    CHECK(s.mean == 2.5);
    CHECK(s.std_dev == doctest::Approx(std::sqrt(1.25)).epsilon(1e-15));
    CHECK(s.skewness == doctest::Approx(0.0));
    CHECK(s.kurtosis == doctest::Approx(2.5625 / (1.25 * 1.25)).epsilon(1e-15));
    CHECK(s.min == 1);
    CHECK(s.max == 4);
    // Skewed: {0, 0, 0, 4}: mean 1, m2 = 3, m3 = (3 * -1 + 27) / 4 = 6, m4 = (3 + 81) / 4 = 21.
    const ChannelStatistics k = channel_statistics({0, 0, 0, 4});
    CHECK(k.skewness == doctest::Approx(6 / std::pow(3.0, 1.5)).epsilon(1e-15));
    CHECK(k.kurtosis == doctest::Approx(21.0 / 9).epsilon(1e-15));
    const ChannelStatistics c = channel_statistics({7, 7, 7});
    CHECK(c.mean == 7);
    CHECK(c.std_dev == 0);
    CHECK(c.kurtosis == 0);
}

TEST_CASE("lifetime DELs: Weibull bins around the runs' speeds") {
    const Weibull iec1 = iec_weibull(WindClass::I);
    CHECK(iec1.scale == doctest::Approx(2 * 10 / std::sqrt(M_PI)).epsilon(1e-15));
    CHECK(iec1.shape == 2);
    // The mean of a Rayleigh distribution with that scale is V_ave = 0.2 V_ref.
    CHECK(iec1.scale * std::tgamma(1.5) == doctest::Approx(10.0).epsilon(1e-14));
    CHECK(iec_weibull(WindClass::III).scale ==
          doctest::Approx(2 * 7.5 / std::sqrt(M_PI)).epsilon(1e-15));

    const Weibull w{10, 2};
    auto F = [](double v) { return 1 - std::exp(-(v / 10) * (v / 10)); };
    // Speeds 8, 12, 12 (two seeds), 16: bins [6, 10], [10, 14], [14, 18].
    const std::vector<double> p = run_probabilities({8, 12, 16, 12}, w);
    CHECK(p[0] == doctest::Approx(F(10) - F(6)).epsilon(1e-14));
    CHECK(p[1] == doctest::Approx((F(14) - F(10)) / 2).epsilon(1e-14));
    CHECK(p[3] == p[1]);
    CHECK(p[2] == doctest::Approx(F(18) - F(14)).epsilon(1e-14));

    const std::vector<double> dels = {100, 200, 300, 220};
    const double m = 4, life = 20 * 365.25 * 86400;
    double sum = 0;
    for (std::size_t i = 0; i < dels.size(); ++i) sum += p[i] * std::pow(dels[i], m);
    CHECK(lifetime_equivalent_load(dels, p, m, life, 1.0, 0) ==
          doctest::Approx(std::pow(sum, 1 / m)).epsilon(1e-13));
    // At N_life = 1e7 cycles instead of one per second of the life.
    CHECK(lifetime_equivalent_load(dels, p, m, life, 1.0, 1e7) ==
          doctest::Approx(std::pow(sum * life / 1e7, 1 / m)).epsilon(1e-13));
}
