#pragma once
// A compiled model's outputs and accelerations at (q, q', u): M q'' = F solved
// with Eigen, the generated `outputs` alongside (the reaction and section tests).
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

} // namespace physics_test
