#pragma once
// Eigen-analysis of a linearised model x' = A x with x = [q, q']: natural
// frequencies, damping ratios and mode shapes, the numbers `yamsc lin` prints
// and a Campbell diagram is made of.
#include "yamsc/model_view.hpp"

#include <complex>
#include <vector>

namespace yamsc::runtime {

struct Mode {
    /// The eigenvalue with Im >= 0 (one of each complex-conjugate pair); 0 for a
    /// rigid-body mode.
    std::complex<double> eigenvalue;
    /// Undamped natural frequency |lambda| in rad/s, and in Hz.
    double omega_n = 0.0;
    double freq_hz = 0.0;
    /// Damped frequency |Im lambda| / 2 pi.
    double damped_freq_hz = 0.0;
    /// -Re(lambda) / |lambda|: 1 for a decaying real mode, negative when unstable;
    /// 0 for a rigid-body mode, whose damping is undefined.
    double damping_ratio = 0.0;
    /// A zero eigenvalue: the model can move freely along `shape` (e.g. a free
    /// rotor azimuth).
    bool rigid_body = false;
    /// A real non-zero eigenvalue: no oscillation (overdamped or divergent).
    bool real = false;
    /// The q part of the eigenvector (nq values) scaled so that its largest
    /// component is exactly 1 (magnitude and phase removed).
    std::vector<std::complex<double>> shape;
};

struct ModalOptions {
    /// Eigenvalues with |lambda| < zero_tolerance * max(1, sqrt(||A||_inf)) are
    /// zero. The square root because a defective zero eigenvalue (a free DOF
    /// without damping) is split by rounding into +-sqrt(eps ||A||).
    double zero_tolerance = 1e-6;
};

/// A shape scaled so that its largest entry is exactly 1 (unchanged when it is 0).
std::vector<std::complex<double>> normalized_shape(const std::vector<std::complex<double>>& shape);

/// The mode of eigenvalue lambda (Im >= 0, not zero) whose coordinates move as
/// `shape`: its frequencies, damping ratio and the shape normalized.
Mode dynamic_mode(std::complex<double> lambda, const std::vector<std::complex<double>>& shape);

/// The modes of the row-major 2nq x 2nq state matrix A, sorted by frequency
/// (then by damping ratio). Rigid-body modes come first, one per independent
/// free direction. Throws std::invalid_argument when A has the wrong size or is
/// not finite.
std::vector<Mode> modal_analysis(const std::vector<double>& A, int nq,
                                 const ModalOptions& options = {});

/// The state matrix A = d(rhs)/dx (row-major, 2nq x 2nq) of the view at the
/// operating point (x0, u0, t): the model's exact Jacobian, or central
/// differences of rhs when the view has none.
std::vector<double> state_matrix_from_view(const ModelView& view, const std::vector<double>& x0,
                                           const std::vector<double>& u0, double t = 0.0);

} // namespace yamsc::runtime
