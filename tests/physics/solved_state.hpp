#pragma once
// A compiled model's outputs and accelerations at (q, q', u): M q'' = F solved
// with Eigen, the generated `outputs` alongside, and static equilibria (the
// reaction and section tests).
#include <yamsc/model_view.hpp>

#include <Eigen/Dense>

#include <vector>

namespace physics_test {

struct State {
    std::vector<double> y, qdd;
};

inline State at(const yamsc::runtime::ModelView& v, const std::vector<double>& q,
                const std::vector<double>& qd, const std::vector<double>& u = {}) {
    const auto n = static_cast<Eigen::Index>(v.nq);
    std::vector<double> M(static_cast<std::size_t>(n * n)), F(static_cast<std::size_t>(n));
    const double* up = u.empty() ? nullptr : u.data();
    v.mass_matrix(0.0, q.data(), up, M.data());
    v.forcing(0.0, q.data(), qd.data(), up, F.data());
    Eigen::MatrixXd Mm(n, n);
    Eigen::VectorXd Fv(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        Fv(i) = F[static_cast<std::size_t>(i)];
        for (Eigen::Index j = 0; j < n; ++j) Mm(i, j) = M[static_cast<std::size_t>(i * n + j)];
    }
    const Eigen::VectorXd a = Mm.ldlt().solve(Fv);
    State s;
    s.qdd.assign(a.data(), a.data() + n);
    s.y.resize(static_cast<std::size_t>(v.ny));
    v.outputs(0.0, q.data(), qd.data(), up, s.y.data());
    return s;
}

/// Newton's iterations on F(q, 0) = 0 from q: a static equilibrium.
inline std::vector<double> equilibrium(const yamsc::runtime::ModelView& v, std::vector<double> q) {
    const auto n = static_cast<Eigen::Index>(v.nq);
    std::vector<double> zero(q.size(), 0.0), F(q.size()), dq(q.size() * q.size()), dqd(dq.size());
    for (int it = 0; it < 50; ++it) {
        v.forcing(0.0, q.data(), zero.data(), nullptr, F.data());
        v.jacobians(0.0, q.data(), zero.data(), nullptr, dq.data(), dqd.data(), nullptr);
        Eigen::MatrixXd J(n, n);
        Eigen::VectorXd r(n);
        for (Eigen::Index i = 0; i < n; ++i) {
            r(i) = F[static_cast<std::size_t>(i)];
            for (Eigen::Index j = 0; j < n; ++j) J(i, j) = dq[static_cast<std::size_t>(i * n + j)];
        }
        Eigen::VectorXd step = J.lu().solve(r);
        for (Eigen::Index i = 0; i < n; ++i) q[static_cast<std::size_t>(i)] -= step(i);
        if (step.norm() < 1e-15) break;
    }
    return q;
}

} // namespace physics_test
