#pragma once
// The multi-blade coordinate transform of a three-bladed rotor (MBC3, Bir
// 2008, NREL/CP-500-42743): the DOFs of each blade "family" (blade 1, 2, 3's
// first flap mode, say) become one collective and two cyclic (cosine, sine)
// coordinates in the fixed frame,
//
//   q_b = q_0 + q_c cos ψ_b + q_s sin ψ_b,   ψ_b = ψ + (b − 1) 2π/3,
//
// so that a rotor's periodic linear model becomes (nearly) time-invariant and
// can be averaged over azimuth and eigen-analysed. x = [q, q'] = T x_nr with
// T = [[T1, 0], [Ω T2, T1]], T2 = dT1/dψ; then A_nr = T⁻¹ (A T − dT/dt) and
// B_nr = T⁻¹ B, for a constant rotor speed Ω.
#include "yamsc/model_view.hpp"

#include <array>
#include <complex>
#include <string>
#include <vector>

namespace yamsc::runtime {

/// The DOF indices (into q) of blades 1, 2 and 3 of one family; in the
/// transformed coordinates these slots hold the collective, cosine and sine
/// coordinates.
using BladeFamily = std::array<int, 3>;

/// A_nr of the row-major 2nq x 2nq state matrix A at blade-1 azimuth ψ and
/// rotor speed Ω. Throws std::invalid_argument for wrong sizes or indices.
std::vector<double> mbc3_state_matrix(const std::vector<double>& A, int nq,
                                      const std::vector<BladeFamily>& families, double psi,
                                      double omega);

/// The average of mbc3_state_matrix over `azimuths` equally spaced blade-1
/// azimuths, with A(ψ) supplied by the caller (the model linearized there).
template <class StateMatrixAt>
std::vector<double> mbc3_averaged(StateMatrixAt&& A_at, int nq,
                                  const std::vector<BladeFamily>& families, double omega,
                                  int azimuths);

/// The whirl of a mode from its shape in MBC3 coordinates (Im λ > 0): the
/// cosine and sine coordinates of one family. forward: the pattern turns with
/// the rotor (q_s lags q_c by 90°); backward: against it; none: no cyclic part.
enum class Whirl { none, forward, backward };
Whirl whirl_of(std::complex<double> cosine, std::complex<double> sine);

/// The state matrix (row-major, 2n x 2n for the n free DOFs, x = [q_f, q_f'])
/// of the view at (x0, u0, t) with the DOFs in `held` moving as prescribed:
/// their value and rate fixed and their acceleration zero (a rotor at a set
/// speed, a locked generator). The held DOFs' equations drop out and their
/// inertia coupling with them:
///   M_ff δq_f'' = (∂F_f/∂q_f − ∂(M_ff a_f)/∂q_f) δq_f + ∂F_f/∂q_f' δq_f',
/// a_f = M_ff⁻¹ F_f, with ∂M/∂q by central differences of the generated M
/// (it multiplies a_f, zero at an equilibrium). Needs mass_matrix, forcing
/// and jacobians.
std::vector<double> state_matrix_with_held(const ModelView& view, const std::vector<double>& x0,
                                           const std::vector<double>& u0,
                                           const std::vector<int>& held, double t = 0.0);

// ---- implementation of the template

template <class StateMatrixAt>
std::vector<double> mbc3_averaged(StateMatrixAt&& A_at, int nq,
                                  const std::vector<BladeFamily>& families, double omega,
                                  int azimuths) {
    std::vector<double> sum;
    for (int k = 0; k < azimuths; ++k) {
        const double psi = 2.0 * 3.14159265358979323846 * k / azimuths;
        const std::vector<double> a = mbc3_state_matrix(A_at(psi), nq, families, psi, omega);
        if (sum.empty()) sum.assign(a.size(), 0.0);
        for (std::size_t i = 0; i < a.size(); ++i) sum[i] += a[i] / azimuths;
    }
    return sum;
}

} // namespace yamsc::runtime
