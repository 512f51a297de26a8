#include "yamsc/linear_view.hpp"

#include "yamsc/integration.hpp"
#include "yamsc/modal.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace yamsc::runtime {

namespace {
using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
}

LinearSystem linearize_view(const ModelView& view, const std::vector<double>& x0,
                            const std::vector<double>& u0, double t0) {
    check_initial_state(view, x0);
    check_input_size(view, u0);
    if (!view.rhs) throw std::invalid_argument("the model view has no right-hand side");
    LinearSystem s;
    s.nq = view.nq;
    s.nu = view.nu;
    s.x0 = x0;
    s.u0 = u0;
    s.t0 = t0;
    const auto nx = static_cast<std::size_t>(view.nx());
    const auto nq = static_cast<std::size_t>(view.nq);
    const auto nu = static_cast<std::size_t>(view.nu);
    s.f0.assign(nx, 0.0);
    view.rhs(t0, x0.data(), u0.data(), s.f0.data());
    s.A = state_matrix_from_view(view, x0, u0, t0);
    s.B.assign(nx * nu, 0.0);
    if (nu == 0) return s;
    if (view.mass_matrix && view.jacobians) {
        // B = [0; M^-1 dF/du]: the inputs enter the accelerations only.
        RowMajor M(view.nq, view.nq), dq(view.nq, view.nq), dqd(view.nq, view.nq),
            du(view.nq, view.nu);
        const double* q = x0.data();
        const double* qd = x0.data() + nq;
        view.mass_matrix(t0, q, u0.data(), M.data());
        view.jacobians(t0, q, qd, u0.data(), dq.data(), dqd.data(), du.data());
        const RowMajor lower = Eigen::MatrixXd(M).ldlt().solve(Eigen::MatrixXd(du));
        for (std::size_t i = 0; i < nq; ++i)
            for (std::size_t j = 0; j < nu; ++j)
                s.B[(nq + i) * nu + j] =
                    lower(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        return s;
    }
    // No generated Jacobians: central differences of rhs in u.
    std::vector<double> u = u0, plus(nx), minus(nx);
    for (std::size_t j = 0; j < nu; ++j) {
        const double h = 6e-6 * std::max(1.0, std::abs(u0[j]));
        u[j] = u0[j] + h;
        view.rhs(t0, x0.data(), u.data(), plus.data());
        u[j] = u0[j] - h;
        view.rhs(t0, x0.data(), u.data(), minus.data());
        u[j] = u0[j];
        for (std::size_t i = 0; i < nx; ++i) s.B[i * nu + j] = (plus[i] - minus[i]) / (2.0 * h);
    }
    return s;
}

ModelView linear_view(const ModelView& nonlinear, const LinearSystem& system) {
    if (system.nq != nonlinear.nq || system.nu != nonlinear.nu)
        throw std::invalid_argument("the linear system does not belong to this view");
    ModelView v;
    v.nq = nonlinear.nq;
    v.nu = nonlinear.nu;
    v.ny = nonlinear.ny;
    v.dof_names = nonlinear.dof_names;
    v.input_names = nonlinear.input_names;
    v.output_names = nonlinear.output_names;
    auto s = std::make_shared<const LinearSystem>(system);
    v.rhs = [s](double, const double* x, const double* u, double* xdot) {
        const auto nx = s->x0.size();
        const auto nu = s->u0.size();
        for (std::size_t i = 0; i < nx; ++i) {
            double sum = s->f0[i];
            const double* a = s->A.data() + i * nx;
            for (std::size_t j = 0; j < nx; ++j) sum += a[j] * (x[j] - s->x0[j]);
            const double* b = s->B.data() + i * nu;
            for (std::size_t j = 0; j < nu; ++j) sum += b[j] * (u[j] - s->u0[j]);
            xdot[i] = sum;
        }
    };
    v.rhs_jacobian = [s](double, const double*, const double*, double* J) {
        std::copy(s->A.begin(), s->A.end(), J);
    };
    v.outputs = nonlinear.outputs;
    return v;
}

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

} // namespace yamsc::runtime
