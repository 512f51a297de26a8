#include "yamsc/second_order.hpp"

#include <Eigen/Dense>

#include <stdexcept>

namespace yamsc::runtime {

namespace {
using Dense = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::vector<double> flat(const Dense& m) {
    return std::vector<double>(m.data(), m.data() + m.size());
}
} // namespace

SecondOrderModel second_order_model(const ModelView& v, const std::vector<double>& q,
                                    const std::vector<double>& qd, const std::vector<double>& u,
                                    double t) {
    const int nq = v.nq, nu = v.nu;
    if (static_cast<int>(q.size()) != nq || static_cast<int>(qd.size()) != nq ||
        static_cast<int>(u.size()) != nu)
        throw std::invalid_argument("second_order_model: the point has the wrong size");
    if (nq == 0)
        throw std::invalid_argument("second_order_model: the model has no DOF (its motion is "
                                    "all prescribed): there is nothing to linearize");
    if (!v.mass_matrix || !v.forcing || !v.jacobians)
        throw std::invalid_argument("second_order_model: the model was compiled without its "
                                    "mass_matrix, forcing or jacobians routine");
    const double* up = nu ? u.data() : nullptr;
    Dense M(nq, nq), dq(nq, nq), dqd(nq, nq), du(nq, std::max(nu, 1));
    Eigen::VectorXd F(nq);
    v.mass_matrix(t, q.data(), up, M.data());
    v.forcing(t, q.data(), qd.data(), up, F.data());
    v.jacobians(t, q.data(), qd.data(), up, dq.data(), dqd.data(), du.data());
    Eigen::LDLT<Eigen::MatrixXd> ldlt(M);
    const Eigen::VectorXd qdd = ldlt.solve(F);

    SecondOrderModel out;
    out.nq = nq;
    out.nu = nu;
    std::vector<double> x0 = q;
    x0.insert(x0.end(), qd.begin(), qd.end());
    out.A = state_matrix_from_view(v, x0, u, t);
    Dense A_lower(nq, nq);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nq; ++j)
            A_lower(i, j) = out.A[static_cast<std::size_t>((nq + i) * 2 * nq + j)];
    const Dense Q0 = du.leftCols(nu);
    Dense B = Dense::Zero(2 * nq, nu);
    if (nu) B.bottomRows(nq) = ldlt.solve(Eigen::MatrixXd(Q0));
    out.M0 = flat(M);
    out.C0 = flat(-dqd);
    out.K0 = flat(-(M * A_lower));
    out.Q0 = flat(Q0);
    out.B = flat(B);
    out.F0.assign(F.data(), F.data() + nq);
    out.equilibrium_residual = nq ? qdd.cwiseAbs().maxCoeff() : 0.0;
    out.modes = modal_analysis(out.A, nq);
    return out;
}

} // namespace yamsc::runtime
