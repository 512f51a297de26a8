#pragma once
// Rainflow counting and damage-equivalent loads.
//
// Counting follows ASTM E1049-85 (reapproved 2017), 5.4.4: the series is reduced
// to its turning points (plateaus belong to the slope before them; the first and
// last samples are kept), then ranges are taken off a stack: a range Y not
// larger than the next X is a full cycle, or a half cycle when Y holds the
// first point; what is left at the end counts as half cycles. This is
// openfast_toolbox's `rainflow_astm` (fatigue.py, from DTU's wetb and
// Nieslony's code) cycle for cycle.
//
// The damage-equivalent load over a series of duration T at the equivalent
// frequency f_eq is DEL = (sum_i n_i S_i^m / (f_eq T))^(1/m), n_i the cycle counts
// (half cycles 0.5), S_i their ranges, m the Wöhler exponent: openfast_toolbox's
// `equivalent_load` and pCrunch's `compute_del`. With bins (openfast_toolbox's
// default, 100), ranges are first put into that many equal bins between the
// smallest and the largest range, each bin then counting its cycles at the mean
// of its ranges (openfast_toolbox: meanBin=True, binStartAt0=False, NumPy's
// histogram edges: half open, the last one closed).
#include <vector>

namespace yamsc::analysis {

struct Cycle {
    double range = 0; ///< peak to valley, > 0
    double mean = 0;  ///< (peak + valley) / 2
    double count = 0; ///< 0.5 (a half cycle) or 1
};

/// The turning points of `y`: the first sample, each sample where the slope
/// changes sign (a plateau takes the sign before it), the last sample.
std::vector<double> turning_points(const std::vector<double>& y);

/// The cycles of `y`, in the order ASTM E1049's procedure finds them (full
/// cycles as they close, then the residue's half cycles). Ranges of 0 are dropped.
std::vector<Cycle> rainflow(const std::vector<double>& y);

/// openfast_toolbox's default counting, `rainflow_windap` (after DTU's wetb; the
/// IEA "Recommended Practices for Wind Turbine Testing - 3. Fatigue Loads", 2nd
/// ed. 1990, Appendix A), for comparison with its numbers: the series is shifted
/// to start at its minimum, rounded to 255 levels (half to even), reduced to the
/// peaks and troughs at least 255/50 levels apart, counted by pair ranges (full
/// cycles twice as half cycles, the residue as half cycles), and each range
/// rounded to a multiple of 255/50 levels. Not ASTM E1049: ranges are those of
/// the rounded series. A constant series has no cycles.
std::vector<Cycle> rainflow_windap(const std::vector<double>& y);

enum class Counting { astm, windap };

struct EquivalentLoadOptions {
    double frequency = 1.0; ///< f_eq [Hz]
    int bins = 100;         ///< 0: every range as it is
};

/// The DEL of `cycles` over `duration` seconds for Wöhler exponent `m` (> 0); 0
/// without cycles.
double equivalent_load(const std::vector<Cycle>& cycles, double m, double duration,
                       const EquivalentLoadOptions& options);

} // namespace yamsc::analysis
