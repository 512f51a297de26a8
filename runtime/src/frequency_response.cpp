#include "yamsc/frequency_response.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <string>

namespace yamsc::runtime {

namespace {

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ComplexMatrix = Eigen::MatrixXcd;

Eigen::Map<const Matrix> square(const std::vector<double>& m, int n, const char* what) {
    if (m.size() != static_cast<std::size_t>(n) * static_cast<std::size_t>(n))
        throw std::invalid_argument(std::string("frequency_response: ") + what + " is not " +
                                    std::to_string(n) + " x " + std::to_string(n));
    return Eigen::Map<const Matrix>(m.data(), n, n);
}

} // namespace

std::vector<Complex> frequency_response(const LinearDynamics& model, double omega,
                                        const FrequencyTerms& terms) {
    const int n = model.n;
    if (terms.excitation.size() != static_cast<std::size_t>(n))
        throw std::invalid_argument("frequency_response: the excitation has " +
                                    std::to_string(terms.excitation.size()) + " values for " +
                                    std::to_string(n) + " DOFs");
    Matrix mass = square(model.M, n, "M");
    Matrix damping = square(model.C, n, "C");
    if (!terms.added_mass.empty()) mass += square(terms.added_mass, n, "A(w)");
    if (!terms.damping.empty()) damping += square(terms.damping, n, "B(w)");
    const ComplexMatrix z = (-omega * omega * mass + square(model.K, n, "K")).cast<Complex>() +
                            Complex(0, omega) * damping.cast<Complex>();
    const Eigen::Map<const Eigen::VectorXcd> f(terms.excitation.data(), n);
    const Eigen::FullPivLU<ComplexMatrix> lu(z);
    if (!lu.isInvertible())
        throw std::invalid_argument("frequency_response: the impedance is singular at w = " +
                                    std::to_string(omega) + " rad/s");
    const Eigen::VectorXcd x = lu.solve(f);
    return std::vector<Complex>(x.data(), x.data() + n);
}

SeaResponse sea_response(const std::vector<double>& omega,
                         const std::vector<std::vector<Complex>>& rao,
                         const std::vector<double>& spectrum) {
    if (rao.size() != omega.size() || spectrum.size() != omega.size())
        throw std::invalid_argument("sea_response: the frequencies, responses and spectrum "
                                    "differ in length");
    SeaResponse r;
    const std::size_t n = rao.empty() ? 0 : rao.front().size();
    r.variance.assign(n, 0.0);
    for (std::size_t k = 0; k < omega.size(); ++k) {
        if (rao[k].size() != n)
            throw std::invalid_argument("sea_response: responses of different sizes");
        if (k > 0 && !(omega[k] > omega[k - 1]))
            throw std::invalid_argument("sea_response: the frequencies do not increase");
        std::vector<double> s(n);
        for (std::size_t j = 0; j < n; ++j) s[j] = std::norm(rao[k][j]) * spectrum[k];
        r.spectra.push_back(std::move(s));
        if (k > 0)
            for (std::size_t j = 0; j < n; ++j)
                r.variance[j] +=
                    0.5 * (omega[k] - omega[k - 1]) * (r.spectra[k][j] + r.spectra[k - 1][j]);
    }
    for (double v : r.variance) r.standard_deviation.push_back(std::sqrt(v));
    return r;
}

std::vector<std::vector<Complex>> output_responses(const std::vector<std::vector<Complex>>& rao,
                                                   const std::vector<double>& Cy, int ny) {
    std::vector<std::vector<Complex>> y;
    for (const std::vector<Complex>& x : rao) {
        const std::size_t n = x.size();
        if (Cy.size() != static_cast<std::size_t>(ny) * n)
            throw std::invalid_argument("output_responses: the output matrix is not ny x n");
        std::vector<Complex> row(static_cast<std::size_t>(ny));
        for (std::size_t i = 0; i < row.size(); ++i)
            for (std::size_t j = 0; j < n; ++j) row[i] += Cy[i * n + j] * x[j];
        y.push_back(std::move(row));
    }
    return y;
}

} // namespace yamsc::runtime
