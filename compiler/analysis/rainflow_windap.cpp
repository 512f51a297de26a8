// openfast_toolbox's `rainflow_windap` counting (rainflow.hpp), kept apart from the
// ASTM counting yamsc uses by default: it reproduces that tool's numbers.
#include "analysis/rainflow.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::analysis {

namespace {

constexpr double levels = 255.0;
constexpr double threshold = 255.0 / 50; // levels: smaller ranges are not counted

/// The peaks and troughs of `x` that are at least `threshold` apart (the practice's
/// state machine: before the first such pair, then looking for a trough or a peak),
/// and the last running extreme.
std::vector<long> peaks_and_troughs(const std::vector<long>& x) {
    enum class State { begin, trough, peak };
    std::vector<long> s;
    long trough = x[0], peak = x[0];
    State state = State::begin;
    for (std::size_t i = 1; i < x.size(); ++i) {
        const long v = x[i];
        if (state == State::begin) {
            if (v > peak) {
                peak = v;
                if (peak - trough >= threshold) {
                    s.push_back(trough);
                    state = State::peak;
                }
            } else if (v < trough) {
                trough = v;
                if (peak - trough >= threshold) {
                    s.push_back(peak);
                    state = State::trough;
                }
            }
        } else if (state == State::trough) {
            if (v < trough) {
                trough = v;
            } else if (v - trough >= threshold) {
                s.push_back(trough);
                peak = v;
                state = State::peak;
            }
        } else {
            if (v > peak) {
                peak = v;
            } else if (peak - v >= threshold) {
                s.push_back(peak);
                trough = v;
                state = State::trough;
            }
        }
    }
    // The last extreme; never left the start: the middle (an integer, truncated).
    s.push_back(state == State::peak     ? peak
                : state == State::trough ? trough
                                         : (trough + peak) / 2);
    return s;
}

} // namespace

std::vector<Cycle> rainflow_windap(const std::vector<double>& y) {
    if (y.size() < 2) return {};
    const double offset = *std::min_element(y.begin(), y.end());
    std::vector<double> shifted(y.size());
    for (std::size_t i = 0; i < y.size(); ++i) shifted[i] = y[i] - offset;
    const double top = *std::max_element(shifted.begin(), shifted.end());
    if (!(top > 0)) return {};
    const double gain = top / levels;
    std::vector<long> x(y.size());
    for (std::size_t i = 0; i < y.size(); ++i)
        x[i] = static_cast<long>(std::nearbyint(shifted[i] / gain)); // half to even, as np.round
    const std::vector<long> extremes = peaks_and_troughs(x);
    if (extremes.size() < 2) return {};
    const long lowest = *std::min_element(extremes.begin(), extremes.end());

    std::vector<Cycle> cycles;
    auto add = [&](double a, double b, double count) {
        // Range and mean rounded to multiples of the threshold, back in the signal's units.
        const double range = std::nearbyint(std::abs(a - b) / threshold) * gain * threshold;
        const double mean = std::nearbyint((a + b) / 2 / threshold) * gain * threshold + offset;
        cycles.push_back({range, mean, count});
    };
    // Pair-range counting on a stack (the practice's S, p): a range inside the
    // two around it is a full cycle, taken out; what is left is half cycles.
    std::vector<double> s;
    for (long e : extremes) {
        s.push_back(static_cast<double>(e - lowest));
        while (s.size() >= 4) {
            const std::size_t p = s.size() - 1;
            const bool up = s[p - 2] > s[p - 3] && s[p - 1] >= s[p - 3] && s[p] >= s[p - 2];
            const bool down = s[p - 2] < s[p - 3] && s[p - 1] <= s[p - 3] && s[p] <= s[p - 2];
            if (!up && !down) break;
            add(s[p - 2], s[p - 1], 1.0);
            s[p - 2] = s[p];
            s.resize(p - 1);
        }
    }
    for (std::size_t q = 0; q + 1 < s.size(); ++q) add(s[q + 1], s[q], 0.5);
    return cycles;
}

} // namespace yamsc::analysis
