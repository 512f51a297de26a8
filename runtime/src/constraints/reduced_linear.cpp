// lin on a constrained view: the linear model in the independent coordinates
// and speeds, its modes, and for holonomic models M, C, K.
#include "yamsc/constraints.hpp"

#include "rows.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::runtime {

using constraints::at;
using constraints::Matrix;
using constraints::Vector;

namespace {

std::vector<double> flat(const Matrix& m) {
    return std::vector<double>(m.data(), m.data() + m.size());
}

/// The independent rows of x (P with P T = I): coordinates, speeds, block states.
std::vector<int> independent_rows(const ModelView& v, const DependentChoice& c) {
    std::vector<int> rows = c.independent_coordinates;
    for (int j : c.independent_speeds) rows.push_back(v.nq + j);
    for (int k = 0; k < v.nz; ++k) rows.push_back(2 * v.nq + k);
    return rows;
}

/// A shape in all coordinates, its largest entry 1.
std::vector<std::complex<double>> normalized(const Eigen::VectorXcd& q) {
    return normalized_shape({q.data(), q.data() + q.size()});
}

/// The modes of a reduced A that is not [q, q'] (nonholonomic rows or block
/// states): one per eigenvalue with Im >= 0, shapes in all coordinates.
std::vector<Mode> general_modes(const Matrix& A, const Matrix& Tq) {
    const Eigen::EigenSolver<Eigen::MatrixXd> es{Eigen::MatrixXd(A)};
    const double zero = 1e-6 * std::max(1.0, std::sqrt(A.cwiseAbs().rowwise().sum().maxCoeff()));
    std::vector<Mode> modes;
    for (Eigen::Index k = 0; k < A.rows(); ++k) {
        const std::complex<double> l = es.eigenvalues()[k];
        if (l.imag() < 0) continue;
        const Eigen::VectorXcd q = Tq.cast<std::complex<double>>() * es.eigenvectors().col(k);
        if (std::abs(l) < zero) {
            Mode m;
            m.rigid_body = true;
            m.shape = normalized(q);
            modes.push_back(std::move(m));
        } else {
            modes.push_back(dynamic_mode(l, {q.data(), q.data() + q.size()}));
        }
    }
    std::stable_sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) {
        if (a.rigid_body != b.rigid_body) return a.rigid_body;
        if (a.omega_n != b.omega_n) return a.omega_n < b.omega_n;
        return a.damping_ratio < b.damping_ratio;
    });
    return modes;
}

} // namespace

ReducedLinearModel reduced_linear_model(const ModelView& v, const std::vector<double>& x0,
                                        const std::vector<double>& u0, double t0,
                                        const ConstraintOptions& options) {
    if (v.nc == 0)
        throw std::invalid_argument("reduced_linear_model: the model has no constraints");
    constraints::require_rows(v, "reduced_linear_model");
    if (static_cast<int>(x0.size()) != v.nx() || static_cast<int>(u0.size()) != v.nu)
        throw std::invalid_argument("reduced_linear_model: the point has the wrong size");
    const double* u = constraints::inputs(u0);
    ReducedLinearModel out;
    out.choice = choose_dependent(v, t0, x0.data(), u, options);
    const DependentChoice& c = out.choice;
    out.n_coordinates = static_cast<int>(c.independent_coordinates.size());
    out.n_speeds = static_cast<int>(c.independent_speeds.size());
    out.nz = v.nz;
    out.nu = v.nu;
    for (int j : c.independent_coordinates) out.state_names.push_back(v.dof_names[at(j)]);
    for (int j : c.independent_speeds) out.state_names.push_back(v.dof_names[at(j)] + "'");
    for (const auto& z : v.block_state_names) out.state_names.push_back(z);

    const Matrix T = constraints::tangent_basis(v, t0, x0.data(), u, c);
    const std::vector<int> rows = independent_rows(v, c);
    const int nx = v.nx(), ns = static_cast<int>(rows.size());
    const std::vector<double> Jv = state_matrix_from_view(v, x0, u0, t0);
    const Eigen::Map<const Matrix> J(Jv.data(), nx, nx);
    Matrix P = Matrix::Zero(ns, nx);
    for (int k = 0; k < ns; ++k) P(k, rows[at(k)]) = 1.0;
    const Matrix A = P * J * T;
    // B by central differences of the constrained rhs in u (the KKT solve in u).
    Matrix Bu = Matrix::Zero(ns, v.nu);
    std::vector<double> uu = u0, plus(at(nx)), minus(at(nx));
    for (int j = 0; j < v.nu; ++j) {
        const double h = 6e-6 * std::max(1.0, std::fabs(u0[at(j)]));
        uu[at(j)] = u0[at(j)] + h;
        v.rhs(t0, x0.data(), uu.data(), plus.data());
        uu[at(j)] = u0[at(j)] - h;
        v.rhs(t0, x0.data(), uu.data(), minus.data());
        uu[at(j)] = u0[at(j)];
        for (int k = 0; k < ns; ++k)
            Bu(k, j) = (plus[at(rows[at(k)])] - minus[at(rows[at(k)])]) / (2.0 * h);
    }
    out.T = flat(T);
    out.A = flat(A);
    out.B = flat(Bu);
    const Matrix Tq = T.topRows(v.nq);
    const int m = out.n_coordinates;
    out.second_order = v.nh == v.nc && v.nz == 0;
    if (out.second_order && m > 0) {
        out.modes = modal_analysis(out.A, m);
        for (Mode& mode : out.modes) {
            Eigen::VectorXcd s(m);
            for (int i = 0; i < m; ++i) s[i] = mode.shape[at(i)];
            mode.shape = normalized(Tq.leftCols(m).cast<std::complex<double>>() * s);
        }
        if (v.mass_matrix) {
            Matrix M(v.nq, v.nq);
            v.mass_matrix(t0, x0.data(), u, M.data());
            const Matrix Tm = Tq.leftCols(m);
            const Matrix Mr = Tm.transpose() * M * Tm;
            out.M = flat(Mr);
            out.K = flat(-(Mr * A.bottomLeftCorner(m, m)));
            out.C = flat(-(Mr * A.bottomRightCorner(m, m)));
        }
    } else if (ns > 0) {
        out.modes = general_modes(A, Tq);
    }
    return out;
}

} // namespace yamsc::runtime
