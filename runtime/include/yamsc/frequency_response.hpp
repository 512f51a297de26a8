#pragma once
// The frequency-domain response of a linear model in waves, as RAFT computes a
// floating wind turbine's (docs/hydrodynamics.md, "Frequency-domain response"):
// at each wave frequency w the complex amplitude X(w) of the DOFs per unit wave
// amplitude (the response amplitude operator, RAO),
//
//   X(w) = [-w^2 (M + A(w)) + i w (C + B(w)) + K]^-1 F(w),
//
// M, C, K the linear model's second-order matrices (second_order.hpp), A(w) and
// B(w) what the radiation adds at w beyond them (zero for strip theory), F(w)
// the excitation per unit amplitude: a motion q(t) = Re(X e^{i w t}) for an
// elevation Re(e^{i w t}). For a sea of one-sided spectrum S(w) the response
// spectra are |X|^2 S and the variances their integrals.
#include <complex>
#include <vector>

namespace yamsc::runtime {

using Complex = std::complex<double>;

/// The linear model, n x n row-major matrices.
struct LinearDynamics {
    int n = 0;
    std::vector<double> M, C, K;
};

/// What one frequency adds to the model: the excitation per unit wave amplitude
/// (n values) and, optional (empty: none), the radiation's extra added mass and
/// damping at that frequency (n x n, row-major).
struct FrequencyTerms {
    std::vector<Complex> excitation;
    std::vector<double> added_mass{}, damping{};
};

/// X(w) of `model` at w [rad/s]. Throws std::invalid_argument for wrong sizes
/// and for a singular impedance (w = 0 with a singular K).
std::vector<Complex> frequency_response(const LinearDynamics& model, double omega,
                                        const FrequencyTerms& terms);

/// Response spectra and their statistics on a frequency grid.
struct SeaResponse {
    std::vector<std::vector<double>> spectra; ///< per frequency, |X_j|^2 S(w) per DOF or output
    std::vector<double> variance, standard_deviation; ///< per DOF or output
};

/// The spectra |X_j(w_k)|^2 S(w_k) and their trapezoidal integrals over the grid
/// `omega` (increasing; RAFT's grid is uniform and its sum a rectangle rule:
/// the two agree when S vanishes at the grid's ends). rao[k][j]: X_j(w_k).
SeaResponse sea_response(const std::vector<double>& omega,
                         const std::vector<std::vector<Complex>>& rao,
                         const std::vector<double>& spectrum);

/// The responses of outputs y = Cy q (ny x n row-major) from those of the DOFs.
std::vector<std::vector<Complex>> output_responses(const std::vector<std::vector<Complex>>& rao,
                                                   const std::vector<double>& Cy, int ny);

} // namespace yamsc::runtime
