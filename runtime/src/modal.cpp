#include "yamsc/modal.hpp"

#include "yamsc/integration.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace yamsc::runtime {

namespace {

constexpr double two_pi = 6.283185307179586476925286766559;
// Singular values of the zero-eigenvalue q-parts below this fraction of the
// largest are the near-parallel pair that rounding makes of one defective
// eigenvalue, not a second free direction.
constexpr double rigid_rank_tolerance = 1e-3;

using ComplexVector = Eigen::VectorXcd;

std::vector<std::complex<double>> to_std(const ComplexVector& v) {
    return {v.data(), v.data() + v.size()};
}

// One rigid-body mode per independent direction spanned by the q parts of the
// zero eigenvalues' eigenvectors (an eigenvector [a; b] of 0 has b = 0, a != 0).
std::vector<Mode> rigid_body_modes(const Eigen::MatrixXcd& zero_q_parts) {
    std::vector<Mode> modes;
    if (zero_q_parts.cols() == 0) return modes;
    const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(zero_q_parts, Eigen::ComputeThinU);
    const auto& sigma = svd.singularValues();
    for (Eigen::Index i = 0; i < sigma.size(); ++i) {
        if (sigma[i] <= rigid_rank_tolerance * sigma[0]) break;
        Mode mode;
        mode.rigid_body = true;
        mode.shape = normalized_shape(to_std(svd.matrixU().col(i)));
        modes.push_back(mode);
    }
    return modes;
}

} // namespace

std::vector<std::complex<double>> normalized_shape(const std::vector<std::complex<double>>& shape) {
    if (shape.empty()) return shape;
    std::size_t largest = 0;
    for (std::size_t i = 1; i < shape.size(); ++i)
        if (std::abs(shape[i]) > std::abs(shape[largest])) largest = i;
    const std::complex<double> scale = shape[largest];
    std::vector<std::complex<double>> out(shape.size());
    for (std::size_t i = 0; i < shape.size(); ++i)
        out[i] = scale == 0.0 ? shape[i] : shape[i] / scale;
    out[largest] = 1.0; // exactly, not 1 +- rounding
    return out;
}

Mode dynamic_mode(std::complex<double> lambda, const std::vector<std::complex<double>>& shape) {
    Mode mode;
    mode.eigenvalue = lambda;
    mode.omega_n = std::abs(lambda);
    mode.freq_hz = mode.omega_n / two_pi;
    mode.damped_freq_hz = std::abs(lambda.imag()) / two_pi;
    mode.damping_ratio = -lambda.real() / mode.omega_n;
    mode.real = lambda.imag() == 0.0;
    mode.shape = normalized_shape(shape);
    return mode;
}

std::vector<Mode> modal_analysis(const std::vector<double>& A, int nq,
                                 const ModalOptions& options) {
    if (nq <= 0) throw std::invalid_argument("modal analysis needs at least one DOF");
    const Eigen::Index n = 2 * nq;
    if (A.size() != static_cast<std::size_t>(n * n))
        throw std::invalid_argument("state matrix has " + std::to_string(A.size()) +
                                    " entries, expected " + std::to_string(n * n));
    for (double a : A)
        if (!std::isfinite(a)) throw std::invalid_argument("state matrix is not finite");

    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>
        a(A.data(), n, n);
    const Eigen::EigenSolver<Eigen::MatrixXd> solver(a, true);
    if (solver.info() != Eigen::Success)
        throw std::runtime_error("the eigenvalue iteration did not converge");
    const ComplexVector& lambdas = solver.eigenvalues();
    const Eigen::MatrixXcd vectors = solver.eigenvectors();

    const double zero_tol =
        options.zero_tolerance * std::max(1.0, std::sqrt(a.cwiseAbs().rowwise().sum().maxCoeff()));

    std::vector<Mode> modes;
    std::vector<Eigen::Index> zero_indices;
    for (Eigen::Index k = 0; k < n; ++k) {
        const std::complex<double> lambda = lambdas[k];
        if (std::abs(lambda) < zero_tol) {
            zero_indices.push_back(k);
            continue;
        }
        // Eigen returns complex pairs as exact conjugates and real eigenvalues
        // with an imaginary part of exactly 0: keep the upper member of each pair.
        if (lambda.imag() < 0.0) continue;
        modes.push_back(dynamic_mode(lambda, to_std(vectors.col(k).head(nq))));
    }

    Eigen::MatrixXcd zero_q_parts(nq, static_cast<Eigen::Index>(zero_indices.size()));
    for (std::size_t j = 0; j < zero_indices.size(); ++j)
        zero_q_parts.col(static_cast<Eigen::Index>(j)) = vectors.col(zero_indices[j]).head(nq);
    std::vector<Mode> all = rigid_body_modes(zero_q_parts);

    std::stable_sort(modes.begin(), modes.end(), [](const Mode& x, const Mode& y) {
        if (x.freq_hz != y.freq_hz) return x.freq_hz < y.freq_hz;
        return x.damping_ratio < y.damping_ratio;
    });
    all.insert(all.end(), modes.begin(), modes.end());
    return all;
}

std::vector<double> state_matrix_from_view(const ModelView& view, const std::vector<double>& x0,
                                           const std::vector<double>& u0, double t) {
    check_initial_state(view, x0);
    check_input_size(view, u0);
    const auto n = static_cast<std::size_t>(view.nx());
    std::vector<double> A(n * n);
    if (view.rhs_jacobian) {
        view.rhs_jacobian(t, x0.data(), u0.data(), A.data());
        return A;
    }
    if (!view.rhs) throw std::invalid_argument("the model view has no right-hand side");
    // Central differences, step balanced between truncation (h^2) and rounding
    // (eps / h) errors.
    std::vector<double> x = x0, plus(n), minus(n);
    for (std::size_t j = 0; j < n; ++j) {
        const double h = 6e-6 * std::max(1.0, std::abs(x0[j]));
        x[j] = x0[j] + h;
        view.rhs(t, x.data(), u0.data(), plus.data());
        x[j] = x0[j] - h;
        view.rhs(t, x.data(), u0.data(), minus.data());
        x[j] = x0[j];
        for (std::size_t i = 0; i < n; ++i) A[i * n + j] = (plus[i] - minus[i]) / (2.0 * h);
    }
    return A;
}

} // namespace yamsc::runtime
