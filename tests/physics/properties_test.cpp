// Properties every model must have, checked on the shipped models and the 3D
// test chain at random states: the generated code agrees with the exact
// symbolic evaluation; M is symmetric positive definite; the analytic
// Jacobians agree with central finite differences.
#include "equations_fixture.hpp"

#include <Eigen/Dense>

using namespace yamsc;

namespace {

const std::string models[] = {"models/pendulum.mbd",
                              "models/double_pendulum.mbd",
                              "models/heavy_top.mbd",
                              "models/nrel5mw_spar_rigid.mbd",
                              "models/nrel5mw_land_2dof.mbd",
                              "models/nrel5mw_blade.mbd",
                              "tests/physics/models/tumbling.mbd",
                              "tests/physics/models/free_beam.mbd",
                              "tests/physics/models/tower_top_mass.mbd"};

struct State {
    std::vector<double> q, qd, u;
};

State random_state(const runtime::ModelView& v, std::mt19937& rng) {
    std::uniform_real_distribution<double> U(-1.5, 1.5);
    State s;
    for (int i = 0; i < v.nq; ++i) {
        s.q.push_back(U(rng));
        s.qd.push_back(U(rng));
    }
    for (int i = 0; i < v.nu; ++i) s.u.push_back(1000 * U(rng));
    return s;
}

double rel_err(double a, double b, double scale) {
    return std::fabs(a - b) / std::max(scale, 1e-300);
}

} // namespace

TEST_CASE("generated code agrees with the symbolic equations; M is SPD") {
    for (const std::string& path : models) {
        CAPTURE(path);
        auto eq = test::derive_file(path);
        auto c = test::compile_model(eq);
        const auto& v = c.view;
        const auto n = static_cast<std::size_t>(v.nq);
        std::mt19937 rng(3);
        for (int k = 0; k < 5; ++k) {
            State s = random_state(v, rng);
            std::vector<double> M(n * n), F(n);
            v.mass_matrix(0.3, s.q.data(), s.u.data(), M.data());
            v.forcing(0.3, s.q.data(), s.qd.data(), s.u.data(), F.data());
            auto ref = test::evaluate(eq, s.q, s.qd, s.u, {}, 0.3);
            double mscale = test::max_abs(M), fscale = std::max(test::max_abs(F), mscale);
            for (std::size_t i = 0; i < n; ++i) {
                CHECK(rel_err(F[i], ref.F[i], fscale) < 1e-12);
                for (std::size_t j = 0; j < n; ++j) {
                    CHECK(rel_err(M[i * n + j], ref.M[i][j], mscale) < 1e-12);
                    CHECK(M[i * n + j] == M[j * n + i]);
                }
            }
            Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> Mm(
                M.data(), v.nq, v.nq);
            Eigen::LLT<Eigen::MatrixXd> llt(Mm);
            CHECK(llt.info() == Eigen::Success);
        }
    }
}

TEST_CASE("analytic Jacobians agree with central finite differences") {
    for (const std::string& path : models) {
        CAPTURE(path);
        auto eq = test::derive_file(path);
        auto c = test::compile_model(eq);
        const auto& v = c.view;
        const int nq = v.nq, nu = v.nu;
        const auto n = static_cast<std::size_t>(nq);
        std::mt19937 rng(11);
        for (int k = 0; k < 3; ++k) {
            State s = random_state(v, rng);
            std::vector<double> dq(n * n), dqd(n * n),
                du(n * static_cast<std::size_t>(std::max(nu, 1)));
            v.jacobians(0.1, s.q.data(), s.qd.data(), s.u.data(), dq.data(), dqd.data(), du.data());
            auto F = [&](const State& x) {
                std::vector<double> out(n);
                v.forcing(0.1, x.q.data(), x.qd.data(), x.u.data(), out.data());
                return out;
            };
            double scale = std::max(test::max_abs(F(s)), 1.0);
            auto check_column = [&](std::vector<double>& var, std::size_t col,
                                    const std::vector<double>& J, std::size_t ncols, double h) {
                double keep = var[col];
                var[col] = keep + h;
                auto Fp = F(s);
                var[col] = keep - h;
                auto Fm = F(s);
                var[col] = keep;
                for (std::size_t r = 0; r < n; ++r) {
                    double fd = (Fp[r] - Fm[r]) / (2 * h);
                    CHECK(std::fabs(J[r * ncols + col] - fd) < 1e-6 * scale);
                }
            };
            for (std::size_t j = 0; j < n; ++j) check_column(s.q, j, dq, n, 1e-6);
            for (std::size_t j = 0; j < n; ++j) check_column(s.qd, j, dqd, n, 1e-6);
            for (std::size_t j = 0; j < static_cast<std::size_t>(nu); ++j)
                check_column(s.u, j, du, static_cast<std::size_t>(nu), 1e-3);

            // rhs_jacobian against finite differences of rhs.
            std::vector<double> x = s.q;
            x.insert(x.end(), s.qd.begin(), s.qd.end());
            const std::size_t nx = 2 * n;
            std::vector<double> J(nx * nx), fp(nx), fm(nx), f0(nx);
            v.rhs_jacobian(0.1, x.data(), s.u.data(), J.data());
            v.rhs(0.1, x.data(), s.u.data(), f0.data());
            double xscale = std::max(test::max_abs(f0), 1.0);
            for (std::size_t j = 0; j < nx; ++j) {
                double keep = x[j], h = 1e-6;
                x[j] = keep + h;
                v.rhs(0.1, x.data(), s.u.data(), fp.data());
                x[j] = keep - h;
                v.rhs(0.1, x.data(), s.u.data(), fm.data());
                x[j] = keep;
                for (std::size_t r = 0; r < nx; ++r)
                    CHECK(std::fabs(J[r * nx + j] - (fp[r] - fm[r]) / (2 * h)) < 1e-5 * xscale);
            }
        }
    }
}
