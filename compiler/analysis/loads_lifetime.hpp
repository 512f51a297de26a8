#pragma once
// Lifetime damage-equivalent loads from runs at several mean wind speeds,
// weighted by the probability of each speed (IEC 61400-1 Ed. 3, 6.3.1.1: the
// hub-height mean speed has a Weibull distribution, Rayleigh (k = 2) with mean
// V_ave = 0.2 V_ref for the design classes I, II and III).
//
// The runs' distinct mean speeds V_1 < ... < V_n make the bins: bin j spans from
// the middle between V_j-1 and V_j to the middle between V_j and V_j+1, the outer
// bins as wide on their open side as on the other (half the neighbour's
// distance). p_j = F(hi_j) - F(lo_j), F(V) = 1 - exp(-(V/A)^k), shared equally by
// the runs (seeds) at V_j. A run i of duration T_i and DEL_i (at f_eq) stands for
// p_i T_life of the life, so it brings n_i = p_i T_life / T_i times its cycles:
//   DEL_life = (sum_i p_i T_life f_eq DEL_i^m / N_life)^(1/m),  N_life = f_eq T_life
// by default (then DEL_life = (sum_i p_i DEL_i^m)^(1/m)), or a given N_life (e.g.
// 1e7 cycles). Time outside the bins (below cut-in, parked) brings no damage.
// This is MLife's lifetime DEL (Hayman 2012, MLife theory manual, eq. 30-32) with
// the bins centred on the runs' speeds.
#include <vector>

namespace yamsc::analysis {

struct Weibull {
    double scale = 0; ///< A [m/s]
    double shape = 2; ///< k
    double cdf(double v) const;
};

enum class WindClass { I, II, III };

/// Rayleigh with V_ave = 0.2 V_ref: A = 2 V_ave / sqrt(pi).
Weibull iec_weibull(WindClass c);

/// The probability each run stands for (see above); `speeds` one per run, finite.
std::vector<double> run_probabilities(const std::vector<double>& speeds, const Weibull& w);

/// DEL_life from the runs' DELs and probabilities. `life_cycles` <= 0: f_eq T_life.
double lifetime_equivalent_load(const std::vector<double>& dels,
                                const std::vector<double>& probabilities, double m,
                                double life_seconds, double frequency, double life_cycles);

} // namespace yamsc::analysis
