#include "added_mass.hpp"

#include <Eigen/Dense>

#include <stdexcept>

namespace yamsc::runtime::detail {

namespace {
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstMap = Eigen::Map<const RowMatrix>;
} // namespace

AddedMassTerms added_mass_terms(int nq, int nl, const double* M, const std::vector<double>& qdd0,
                                const std::vector<std::vector<double>>& qdd_k,
                                const std::vector<double>& h) {
    AddedMassTerms t;
    t.nq = nq;
    t.nl = nl;
    t.W.assign(static_cast<std::size_t>(nq * nl), 0.0);
    for (int k = 0; k < nl; ++k)
        for (int r = 0; r < nq; ++r) {
            const std::size_t i = static_cast<std::size_t>(r);
            t.W[static_cast<std::size_t>(r * nl + k)] =
                (qdd_k[static_cast<std::size_t>(k)][i] - qdd0[i]) / h[static_cast<std::size_t>(k)];
        }
    t.G.resize(t.W.size());
    Eigen::Map<RowMatrix>(t.G.data(), nq, nl) = ConstMap(M, nq, nq) * ConstMap(t.W.data(), nq, nl);
    return t;
}

std::vector<double> coupled_accelerations(const AddedMassTerms& t, const double* A,
                                          const std::vector<double>& qdd0) {
    const ConstMap G(t.G.data(), t.nq, t.nl), W(t.W.data(), t.nq, t.nl), Am(A, t.nl, t.nl);
    const Eigen::Map<const Eigen::VectorXd> q0(qdd0.data(), t.nq);
    const Eigen::MatrixXd S = Eigen::MatrixXd::Identity(t.nl, t.nl) + G.transpose() * W * Am;
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(S);
    const Eigen::VectorXd s = lu.solve(G.transpose() * q0);
    if (!s.allFinite())
        throw std::invalid_argument("load block: the added mass makes the accelerations singular");
    return {s.data(), s.data() + s.size()};
}

void add_added_mass(const AddedMassTerms& t, const double* A, double* M) {
    const ConstMap G(t.G.data(), t.nq, t.nl), Am(A, t.nl, t.nl);
    Eigen::Map<RowMatrix>(M, t.nq, t.nq) += G * Am * G.transpose();
}

} // namespace yamsc::runtime::detail
