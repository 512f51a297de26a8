#include "output_matrices.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::python {

namespace {

/// The step of a central difference about `x`: ~cbrt(eps) relative, which
/// balances truncation against rounding.
double step_at(double x) {
    return 6e-6 * std::max(1.0, std::fabs(x));
}

} // namespace

OutputMatrices output_matrices(const runtime::ModelView& v, const std::vector<double>& x0,
                               const std::vector<double>& u0, double t0) {
    if (!v.outputs) throw std::invalid_argument("the model was compiled without its outputs");
    const auto nq = static_cast<std::size_t>(v.nq), nu = static_cast<std::size_t>(v.nu),
               ny = static_cast<std::size_t>(v.ny), nx = 2 * nq;
    std::vector<double> x = x0, u = u0, yp(ny + 1), ym(ny + 1);
    u.push_back(0); // never an empty vector's null data()
    auto y_at = [&](std::vector<double>& y) {
        v.outputs(t0, x.data(), x.data() + nq, u.data(), y.data());
    };
    OutputMatrices out{std::vector<double>(ny * nx), std::vector<double>(ny * nu)};
    auto column = [&](double& value, std::vector<double>& matrix, std::size_t j, std::size_t n) {
        const double saved = value, h = step_at(saved);
        value = saved + h;
        y_at(yp);
        value = saved - h;
        y_at(ym);
        value = saved;
        for (std::size_t i = 0; i < ny; ++i) matrix[i * n + j] = (yp[i] - ym[i]) / (2 * h);
    };
    for (std::size_t j = 0; j < nx; ++j) column(x[j], out.C, j, nx);
    for (std::size_t j = 0; j < nu; ++j) column(u[j], out.D, j, nu);
    return out;
}

} // namespace yamsc::python
