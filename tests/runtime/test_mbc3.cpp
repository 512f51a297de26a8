// runtime::mbc3_state_matrix against its definition: a rotor at rest is a
// similarity (same eigenvalues); a fixed-frame system written in rotating
// blade coordinates (x_rot = T(ψ) x_nr) comes back exactly at every azimuth,
// which checks T, dT/dt and the blade phases; whirl directions by their sign.
#include <yamsc/mbc3.hpp>

#include <doctest/doctest.h>

#include <Eigen/Dense>

#include <cmath>
#include <random>

using namespace yamsc::runtime;

namespace {

using Matrix = Eigen::MatrixXd;

Matrix to_matrix(const std::vector<double>& a, int n) {
    Matrix m(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) m(i, j) = a[static_cast<std::size_t>(i * n + j)];
    return m;
}

std::vector<double> to_vector(const Matrix& m) {
    std::vector<double> out;
    for (int i = 0; i < m.rows(); ++i)
        for (int j = 0; j < m.cols(); ++j) out.push_back(m(i, j));
    return out;
}

// nq = 4: a fixed-frame DOF (0) and one blade family on DOFs 1, 2, 3.
constexpr int nq = 4;
const std::vector<BladeFamily> family{{1, 2, 3}};

/// T(ψ) and dT/dt for the family above, written out independently.
void transform(double psi, double omega, Matrix& T, Matrix& Tdot) {
    const double pi = 3.14159265358979323846;
    Matrix T1 = Matrix::Zero(nq, nq), T2 = Matrix::Zero(nq, nq), T3 = Matrix::Zero(nq, nq);
    T1(0, 0) = 1;
    for (int b = 0; b < 3; ++b) {
        const double a = psi + 2 * pi * b / 3;
        T1(1 + b, 1) = 1;
        T1(1 + b, 2) = std::cos(a);
        T1(1 + b, 3) = std::sin(a);
        T2(1 + b, 2) = -std::sin(a);
        T2(1 + b, 3) = std::cos(a);
        T3(1 + b, 2) = -std::cos(a);
        T3(1 + b, 3) = -std::sin(a);
    }
    T = Matrix::Zero(2 * nq, 2 * nq);
    Tdot = Matrix::Zero(2 * nq, 2 * nq);
    T.topLeftCorner(nq, nq) = T1;
    T.bottomLeftCorner(nq, nq) = omega * T2;
    T.bottomRightCorner(nq, nq) = T1;
    Tdot.topLeftCorner(nq, nq) = omega * T2;
    Tdot.bottomLeftCorner(nq, nq) = omega * omega * T3;
    Tdot.bottomRightCorner(nq, nq) = omega * T2;
}

Matrix random_state_matrix(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    Matrix A = Matrix::Zero(2 * nq, 2 * nq);
    A.topRightCorner(nq, nq).setIdentity();
    for (int i = nq; i < 2 * nq; ++i)
        for (int j = 0; j < 2 * nq; ++j) A(i, j) = d(rng);
    return A;
}

} // namespace

TEST_CASE("mbc3: a rotor at rest is a similarity transform: the eigenvalues stay") {
    const Matrix A = random_state_matrix(7);
    const Eigen::VectorXcd before = A.eigenvalues();
    for (double psi : {0.0, 0.7, 2.0}) {
        const Matrix A_nr = to_matrix(mbc3_state_matrix(to_vector(A), nq, family, psi, 0.0), 8);
        const Eigen::VectorXcd after = A_nr.eigenvalues();
        // Each eigenvalue of A is one of A_nr's.
        for (int i = 0; i < before.size(); ++i) {
            double nearest = 1e300;
            for (int j = 0; j < after.size(); ++j)
                nearest = std::min(nearest, std::abs(before(i) - after(j)));
            CHECK(nearest < 1e-12);
        }
    }
}

TEST_CASE("mbc3: a fixed-frame system seen from the rotating blades comes back at every "
          "azimuth") {
    const Matrix A_nr = random_state_matrix(11);
    const double omega = 1.2671;
    for (double psi : {0.0, 0.3, 1.9, 4.4}) {
        CAPTURE(psi);
        Matrix T, Tdot;
        transform(psi, omega, T, Tdot);
        // x_rot = T x_nr: x_rot' = (T A_nr + Tdot) T⁻¹ x_rot.
        const Matrix A_rot = (T * A_nr + Tdot) * T.inverse();
        const Matrix back =
            to_matrix(mbc3_state_matrix(to_vector(A_rot), nq, family, psi, omega), 8);
        CHECK((back - A_nr).cwiseAbs().maxCoeff() < 1e-12);
    }
    // Averaged over azimuths: the same constant matrix.
    auto A_at = [&](double psi) {
        Matrix T, Tdot;
        transform(psi, omega, T, Tdot);
        return to_vector((T * A_nr + Tdot) * T.inverse());
    };
    const Matrix averaged = to_matrix(mbc3_averaged(A_at, nq, family, omega, 8), 8);
    CHECK((averaged - A_nr).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("mbc3: whirl from the phase of the sine coordinate against the cosine one") {
    using C = std::complex<double>;
    // q_c = cos ωt, q_s = sin ωt: the pattern cos(ψ_b − ωt) turns with the rotor.
    CHECK(whirl_of(C(1, 0), C(0, -1)) == Whirl::forward);
    CHECK(whirl_of(C(1, 0), C(0, 1)) == Whirl::backward);
    CHECK(whirl_of(C(1, 0), C(0.5, 0)) == Whirl::none); // a standing pattern
    CHECK(whirl_of(C(0, 0), C(0, 0)) == Whirl::none);
}

TEST_CASE("state_matrix_with_held: a held DOF's inertia coupling drops out") {
    // Two masses: M = [[m1 + m2, m2], [m2, m2]], K = diag(k1, k2); holding DOF 0
    // leaves m2 q1'' = -k2 q1 (the frequency of mass 2 alone).
    const double m1 = 3, m2 = 2, k1 = 50, k2 = 18;
    ModelView v;
    v.nq = 2;
    v.nu = 0;
    v.mass_matrix = [=](double, const double*, const double*, double* M) {
        M[0] = m1 + m2;
        M[1] = M[2] = M[3] = m2;
    };
    v.forcing = [=](double, const double* q, const double*, const double*, double* F) {
        F[0] = -k1 * q[0];
        F[1] = -k2 * q[1];
    };
    v.jacobians = [=](double, const double*, const double*, const double*, double* dq, double* dqd,
                      double*) {
        dq[0] = -k1;
        dq[1] = dq[2] = 0;
        dq[3] = -k2;
        for (int i = 0; i < 4; ++i) dqd[i] = 0;
    };
    const std::vector<double> A = state_matrix_with_held(v, {0, 0, 0, 0}, {}, {0});
    REQUIRE(A.size() == 4);
    CHECK(A[1] == 1.0);
    CHECK(A[2] == doctest::Approx(-k2 / m2).epsilon(1e-14));
}
