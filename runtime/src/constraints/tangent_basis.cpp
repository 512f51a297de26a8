// The basis of the constraint manifold's tangent space at a point, in the
// independent coordinates and speeds: what lin and trim reduce to.
#include "rows.hpp"

namespace yamsc::runtime::constraints {

Matrix tangent_basis(const ModelView& v, double t, const double* x, const double* u,
                     const DependentChoice& c) {
    const int nq = v.nq, nz = v.nz;
    const int mq = static_cast<int>(c.independent_coordinates.size());
    const int mv = static_cast<int>(c.independent_speeds.size());
    const Matrix B = matrix_b(v, t, x, u);
    Matrix dr_dq(v.nc, nq);
    Vector gamma(v.nc);
    v.constraint_bias(t, x, x + nq, u, gamma.data(), dr_dq.data());
    // Without holonomic rows there is nothing to factor (and Eigen refuses an
    // empty matrix): every coordinate is independent.
    const Eigen::FullPivLU<Matrix> Hd =
        v.nh ? columns_of(B.topRows(v.nh), c.coordinates).fullPivLu() : Eigen::FullPivLU<Matrix>();
    const auto Bd = columns_of(B, c.speeds).fullPivLu();
    Matrix T = Matrix::Zero(2 * nq + nz, mq + mv + nz);
    for (int k = 0; k < mq; ++k) {
        // dq: the independent coordinate moved, the dependent ones following Phi.
        const int j = c.independent_coordinates[static_cast<std::size_t>(k)];
        Vector dq = Vector::Zero(nq);
        dq[j] = 1.0;
        if (v.nh) {
            const Vector dd = Hd.solve(-Vector(B.topRows(v.nh).col(j)));
            for (std::size_t i = 0; i < c.coordinates.size(); ++i)
                dq[c.coordinates[i]] = dd[static_cast<Eigen::Index>(i)];
        }
        // dq': the dependent speeds keep r = 0 (dr/dq dq + B dq' = 0).
        const Vector dv = Bd.solve(-(dr_dq * dq));
        T.col(k).head(nq) = dq;
        for (std::size_t i = 0; i < c.speeds.size(); ++i)
            T(nq + c.speeds[i], k) = dv[static_cast<Eigen::Index>(i)];
    }
    for (int k = 0; k < mv; ++k) {
        const int j = c.independent_speeds[static_cast<std::size_t>(k)];
        const Vector dv = Bd.solve(-Vector(B.col(j)));
        T(nq + j, mq + k) = 1.0;
        for (std::size_t i = 0; i < c.speeds.size(); ++i)
            T(nq + c.speeds[i], mq + k) = dv[static_cast<Eigen::Index>(i)];
    }
    for (int k = 0; k < nz; ++k) T(2 * nq + k, mq + mv + k) = 1.0;
    return T;
}

} // namespace yamsc::runtime::constraints
