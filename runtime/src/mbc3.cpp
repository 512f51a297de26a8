#include "yamsc/mbc3.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::runtime {

namespace {

using Matrix = Eigen::MatrixXd;
using RowMajorMap =
    Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;

constexpr double two_pi_thirds = 2.0 * 3.14159265358979323846 / 3.0;

/// T1 (q = T1 q_nr), T2 = dT1/dψ and T3 = d²T1/dψ².
struct Transform {
    Matrix T1, T2, T3;
};

Transform transform(int nq, const std::vector<BladeFamily>& families, double psi) {
    Transform t{Matrix::Identity(nq, nq), Matrix::Zero(nq, nq), Matrix::Zero(nq, nq)};
    for (const BladeFamily& f : families) {
        for (int b = 0; b < 3; ++b) {
            if (f[b] < 0 || f[b] >= nq)
                throw std::invalid_argument("mbc3: a blade DOF index is out of range");
            const double a = psi + b * two_pi_thirds;
            const int row = f[b];
            t.T1.row(row).setZero();
            t.T1(row, f[0]) = 1.0;
            t.T1(row, f[1]) = std::cos(a);
            t.T1(row, f[2]) = std::sin(a);
            t.T2(row, f[1]) = -std::sin(a);
            t.T2(row, f[2]) = std::cos(a);
            t.T3(row, f[1]) = -std::cos(a);
            t.T3(row, f[2]) = -std::sin(a);
        }
    }
    return t;
}

} // namespace

std::vector<double> mbc3_state_matrix(const std::vector<double>& A, int nq,
                                      const std::vector<BladeFamily>& families, double psi,
                                      double omega) {
    const int nx = 2 * nq;
    if (nq < 0 || A.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(nx))
        throw std::invalid_argument("mbc3: A is not 2nq x 2nq");
    const Transform t = transform(nq, families, psi);
    Matrix T = Matrix::Zero(nx, nx), Tdot = Matrix::Zero(nx, nx);
    T.topLeftCorner(nq, nq) = t.T1;
    T.bottomLeftCorner(nq, nq) = omega * t.T2;
    T.bottomRightCorner(nq, nq) = t.T1;
    Tdot.topLeftCorner(nq, nq) = omega * t.T2;
    Tdot.bottomLeftCorner(nq, nq) = omega * omega * t.T3;
    Tdot.bottomRightCorner(nq, nq) = omega * t.T2;
    const Matrix a = RowMajorMap(A.data(), nx, nx);
    const Matrix a_nr = T.partialPivLu().solve(a * T - Tdot);
    std::vector<double> out(A.size());
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < nx; ++j) out[static_cast<std::size_t>(i * nx + j)] = a_nr(i, j);
    return out;
}

Whirl whirl_of(std::complex<double> cosine, std::complex<double> sine) {
    const double size = std::abs(cosine) + std::abs(sine);
    if (size == 0.0) return Whirl::none;
    // q_c = Re(c e^{iωt}), q_s = Re(s e^{iωt}): the pattern q_b = q_c cos ψ_b +
    // q_s sin ψ_b peaks where ψ_b follows the phase of c - i s; its sense is
    // the sign of Im(conj(c) s).
    const double turn = std::imag(std::conj(cosine) * sine);
    if (std::fabs(turn) < 1e-9 * size * size) return Whirl::none;
    return turn < 0 ? Whirl::forward : Whirl::backward;
}

std::vector<double> state_matrix_with_held(const ModelView& view, const std::vector<double>& x0,
                                           const std::vector<double>& u0,
                                           const std::vector<int>& held, double t) {
    const int nq = view.nq;
    if (x0.size() != static_cast<std::size_t>(2 * nq) ||
        u0.size() != static_cast<std::size_t>(view.nu))
        throw std::invalid_argument("state_matrix_with_held: the point has the wrong size");
    if (!view.mass_matrix || !view.forcing || !view.jacobians)
        throw std::invalid_argument("state_matrix_with_held: the model was compiled without its "
                                    "mass_matrix, forcing or jacobians routine");
    std::vector<int> free;
    for (int i = 0; i < nq; ++i)
        if (std::find(held.begin(), held.end(), i) == held.end()) free.push_back(i);
    const int n = static_cast<int>(free.size());
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const double* u = u0.empty() ? nullptr : u0.data();
    std::vector<double> q(x0.begin(), x0.begin() + nq), qd(x0.begin() + nq, x0.end());
    RowMajor M(nq, nq), dq(nq, nq), dqd(nq, nq), du(nq, std::max(view.nu, 1));
    Eigen::VectorXd F(nq);
    view.mass_matrix(t, q.data(), u, M.data());
    view.forcing(t, q.data(), qd.data(), u, F.data());
    view.jacobians(t, q.data(), qd.data(), u, dq.data(), dqd.data(), du.data());

    Matrix Mff(n, n), K(n, n), C(n, n);
    Eigen::VectorXd Ff(n);
    for (int a = 0; a < n; ++a) {
        Ff(a) = F(free[a]);
        for (int b = 0; b < n; ++b) {
            Mff(a, b) = M(free[a], free[b]);
            K(a, b) = dq(free[a], free[b]);
            C(a, b) = dqd(free[a], free[b]);
        }
    }
    const Eigen::LDLT<Matrix> ldlt(Mff);
    const Eigen::VectorXd acc = ldlt.solve(Ff);
    // -∂(M_ff a_f)/∂q_f at fixed a_f, by central differences of M.
    RowMajor Mp(nq, nq), Mm(nq, nq);
    for (int b = 0; b < n; ++b) {
        const auto j = static_cast<std::size_t>(free[b]);
        const double h = 1e-6 * std::max(1.0, std::fabs(q[j]));
        std::vector<double> qp = q, qm = q;
        qp[j] += h;
        qm[j] -= h;
        view.mass_matrix(t, qp.data(), u, Mp.data());
        view.mass_matrix(t, qm.data(), u, Mm.data());
        for (int a = 0; a < n; ++a) {
            double dMa = 0;
            for (int c = 0; c < n; ++c)
                dMa += (Mp(free[a], free[c]) - Mm(free[a], free[c])) / (2 * h) * acc(c);
            K(a, b) -= dMa;
        }
    }
    Matrix A = Matrix::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    A.bottomLeftCorner(n, n) = ldlt.solve(K);
    A.bottomRightCorner(n, n) = ldlt.solve(C);
    std::vector<double> out(static_cast<std::size_t>(4 * n * n));
    for (int i = 0; i < 2 * n; ++i)
        for (int j = 0; j < 2 * n; ++j) out[static_cast<std::size_t>(i * 2 * n + j)] = A(i, j);
    return out;
}

} // namespace yamsc::runtime
