#include "rows.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace yamsc::runtime::constraints {

void require_rows(const ModelView& v, const char* what) {
    if (!v.constraint_residuals || !v.constraint_matrix || !v.constraint_bias ||
        !v.constraint_jacobians)
        throw std::invalid_argument(std::string(what) +
                                    ": the model was compiled without its constraint routines");
    if (static_cast<int>(v.constraint_names.size()) != v.nc)
        throw std::invalid_argument(std::string(what) + ": the constraint rows have no names");
}

Matrix matrix_b(const ModelView& v, double t, const double* q, const double* u) {
    Matrix B(v.nc, v.nq);
    v.constraint_matrix(t, q, u, B.data());
    return B;
}

void residuals(const ModelView& v, double t, const double* q, const double* qd, const double* u,
               Vector& phi, Vector& r) {
    phi.resize(v.nh);
    r.resize(v.nc);
    v.constraint_residuals(t, q, qd, u, phi.data(), r.data());
}

Matrix mass_action_jacobian(const ModelView& v, double t, const double* q, const double* a,
                            const double* u) {
    const int n = v.nq;
    Matrix D(n, n);
    if (v.mass_action_jacobian) {
        v.mass_action_jacobian(t, q, a, u, D.data());
        return D;
    }
    // M is smooth in q: the central difference's error is h^2 M''' / 6 plus
    // eps / h rounding, both about 1e-11 relative with h ~ cbrt(eps).
    std::vector<double> qs(q, q + n);
    Matrix Mp(n, n), Mm(n, n);
    const Eigen::Map<const Vector> av(a, n);
    for (int j = 0; j < n; ++j) {
        const double q0 = qs[static_cast<std::size_t>(j)];
        const double h = 6e-6 * std::max(1.0, std::fabs(q0));
        qs[static_cast<std::size_t>(j)] = q0 + h;
        v.mass_matrix(t, qs.data(), u, Mp.data());
        qs[static_cast<std::size_t>(j)] = q0 - h;
        v.mass_matrix(t, qs.data(), u, Mm.data());
        qs[static_cast<std::size_t>(j)] = q0;
        D.col(j) = (Mp - Mm) * av / (2.0 * h);
    }
    return D;
}

Kkt::Kkt(const ModelView& v, double t, const double* q, const double* qd, const double* u)
    : nq(v.nq), nc(v.nc), M(v.nq, v.nq), B(v.nc, v.nq), F(v.nq), gamma(v.nc) {
    v.mass_matrix(t, q, u, M.data());
    v.forcing(t, q, qd, u, F.data());
    v.constraint_matrix(t, q, u, B.data());
    Matrix dr_dq(nc, nq);
    v.constraint_bias(t, q, qd, u, gamma.data(), dr_dq.data());
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nq + nc, nq + nc);
    K.topLeftCorner(nq, nq) = M;
    K.topRightCorner(nq, nc) = -B.transpose();
    K.bottomLeftCorner(nc, nq) = B;
    lu.compute(K);
    // The KKT matrix is invertible exactly when B has full row rank and M is
    // positive definite on B's null space; a zero pivot shows as rcond ~ eps.
    if (!(lu.rcond() > 1e-13)) {
        std::ostringstream msg;
        msg << "the constrained equations are singular at t = " << t
            << " s (the constraint rows are dependent there, or the mass matrix is singular "
               "on their null space)";
        throw ConstraintError(ConstraintErrorKind::singular, -1, {}, msg.str());
    }
    Vector rhs(nq + nc);
    rhs << F, -gamma;
    const Vector sol = lu.solve(rhs);
    qdd = sol.head(nq);
    lambda = sol.tail(nc);
}

Eigen::MatrixXd Kkt::solve(const Eigen::MatrixXd& top, const Eigen::MatrixXd& bottom) const {
    Eigen::MatrixXd rhs(nq + nc, top.cols());
    rhs << top, bottom;
    return lu.solve(rhs);
}

Matrix columns_of(const Matrix& m, const std::vector<int>& columns) {
    Matrix out(m.rows(), static_cast<Eigen::Index>(columns.size()));
    for (std::size_t k = 0; k < columns.size(); ++k)
        out.col(static_cast<Eigen::Index>(k)) = m.col(columns[k]);
    return out;
}

} // namespace yamsc::runtime::constraints
