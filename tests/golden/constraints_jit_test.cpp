// A model with constraints compiled on the fly: the loader fills the ModelView's
// constraint fields, the generated rhs solves the constrained motion
// (M q'' = F + B^T lambda, B q'' + gamma = 0), and constraint_jacobians agrees
// with central differences of the compiled constraint_matrix and constraint_bias.
#include "analysis/jit.hpp"
#include "codegen/routines.hpp"
#include "diag/diagnostics.hpp"
#include "driver/pipeline.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>
#include <unistd.h>

using namespace yamsc;

namespace {

const std::string source_dir = YAMSC_SOURCE_DIR;

using Vector = std::vector<double>;

/// Solves the n x n system A x = b (row-major) by Gaussian elimination with pivoting.
Vector solve(std::vector<double> A, Vector b) {
    const std::size_t n = b.size();
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t p = k;
        for (std::size_t i = k + 1; i < n; ++i)
            if (std::fabs(A[i * n + k]) > std::fabs(A[p * n + k])) p = i;
        for (std::size_t j = 0; j < n; ++j) std::swap(A[k * n + j], A[p * n + j]);
        std::swap(b[k], b[p]);
        for (std::size_t i = k + 1; i < n; ++i) {
            const double f = A[i * n + k] / A[k * n + k];
            for (std::size_t j = k; j < n; ++j) A[i * n + j] -= f * A[k * n + j];
            b[i] -= f * b[k];
        }
    }
    Vector x(n);
    for (std::size_t k = n; k-- > 0;) {
        double s = b[k];
        for (std::size_t j = k + 1; j < n; ++j) s -= A[k * n + j] * x[j];
        x[k] = s / A[k * n + k];
    }
    return x;
}

} // namespace

TEST_CASE("a four-bar compiled on the fly: its rows, the constrained rhs and the Jacobians") {
    diag::Diagnostics diags;
    driver::FrontEnd fe = driver::run_front_end(
        source_dir + "/tests/model/constraints/four_bar.mbd", driver::Until::jacobians, diags);
    REQUIRE(!diags.has_errors());
    REQUIRE(fe.system);
    char folder[] = "/tmp/yamsc_constraints_XXXXXX";
    REQUIRE(mkdtemp(folder));
    analysis::JitOptions o;
    o.cache_dir = folder;
    const auto library = analysis::load_compiled_model(*fe.system, o);
    const runtime::ModelView v = library->view(library->default_params());
    REQUIRE(std::system(("rm -rf " + std::string(folder)).c_str()) == 0);

    REQUIRE(v.nq == 3);
    REQUIRE(v.nh == 2);
    REQUIRE(v.nc == 2);
    CHECK(v.constraint_names == std::vector<std::string>{"closing.x", "closing.z"});
    CHECK(v.constraint_dependent == std::vector<int>{1, 2});
    REQUIRE(v.constraint_sources.size() == 2);
    CHECK(v.constraint_sources[0].find("four_bar.mbd:26:1") != std::string::npos);
    CHECK(!v.rhs_jacobian); // the constrained view forms it
    REQUIRE(v.constraint_residuals);
    REQUIRE(v.constraint_matrix);
    REQUIRE(v.constraint_bias);
    REQUIRE(v.constraint_jacobians);
    REQUIRE(v.mass_matrix);
    REQUIRE(v.forcing);

    const std::size_t nq = 3, nc = 2;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    for (int trial = 0; trial < 4; ++trial) {
        Vector x(2 * nq), lambda(nc), a(nq);
        for (double& e : x) e = d(rng);
        for (double& e : lambda) e = d(rng);
        for (double& e : a) e = d(rng);
        const double* q = x.data();
        const double* qd = x.data() + nq;
        // The constrained rhs: B q'' + gamma = 0 and M q'' - F in the span of B^T.
        Vector xdot(2 * nq), M(nq * nq), F(nq), B(nc * nq), gamma(nc), dr_dq(nc * nq);
        v.rhs(0.0, x.data(), nullptr, xdot.data());
        v.mass_matrix(0.0, q, nullptr, M.data());
        v.forcing(0.0, q, qd, nullptr, F.data());
        v.constraint_matrix(0.0, q, nullptr, B.data());
        v.constraint_bias(0.0, q, qd, nullptr, gamma.data(), dr_dq.data());
        for (std::size_t i = 0; i < nq; ++i) CHECK(xdot[i] == doctest::Approx(qd[i]));
        const double* qdd = xdot.data() + nq;
        for (std::size_t i = 0; i < nc; ++i) {
            double acc = gamma[i];
            for (std::size_t k = 0; k < nq; ++k) acc += B[i * nq + k] * qdd[k];
            CHECK(std::fabs(acc) < 1e-10);
        }
        Vector residual(nq), BBt(nc * nc, 0.0), Br(nc, 0.0);
        for (std::size_t i = 0; i < nq; ++i) {
            residual[i] = -F[i];
            for (std::size_t k = 0; k < nq; ++k) residual[i] += M[i * nq + k] * qdd[k];
        }
        for (std::size_t i = 0; i < nc; ++i)
            for (std::size_t k = 0; k < nq; ++k) {
                Br[i] += B[i * nq + k] * residual[k];
                for (std::size_t j = 0; j < nc; ++j)
                    BBt[i * nc + j] += B[i * nq + k] * B[j * nq + k];
            }
        const Vector l = solve(BBt, Br); // M q'' - F = B^T l
        for (std::size_t k = 0; k < nq; ++k) {
            double s = residual[k];
            for (std::size_t i = 0; i < nc; ++i) s -= B[i * nq + k] * l[i];
            CHECK(std::fabs(s) < 1e-9 * (1 + std::fabs(residual[k])));
        }
        // constraint_jacobians against central differences of the compiled rows.
        Vector dBTl_dq(nq * nq), dacc_dq(nc * nq), dacc_dqd(nc * nq), none(1);
        v.constraint_jacobians(0.0, q, qd, nullptr, lambda.data(), a.data(), dBTl_dq.data(),
                               dacc_dq.data(), dacc_dqd.data(), none.data(), none.data());
        auto rows = [&](const Vector& xs) {
            Vector Bx(nc * nq), gx(nc), dx(nc * nq), out(nq + nc, 0.0);
            v.constraint_matrix(0.0, xs.data(), nullptr, Bx.data());
            v.constraint_bias(0.0, xs.data(), xs.data() + nq, nullptr, gx.data(), dx.data());
            for (std::size_t i = 0; i < nc; ++i) {
                out[nq + i] = gx[i];
                for (std::size_t k = 0; k < nq; ++k) {
                    out[k] += Bx[i * nq + k] * lambda[i];
                    out[nq + i] += Bx[i * nq + k] * a[k];
                }
            }
            return out;
        };
        const double h = 1e-6;
        for (std::size_t j = 0; j < 2 * nq; ++j) {
            Vector xp = x, xm = x;
            xp[j] += h;
            xm[j] -= h;
            const Vector rp = rows(xp), rm = rows(xm);
            for (std::size_t i = 0; i < nq + nc; ++i) {
                const double fd = (rp[i] - rm[i]) / (2 * h);
                double exact;
                if (j < nq)
                    exact = i < nq ? dBTl_dq[i * nq + j] : dacc_dq[(i - nq) * nq + j];
                else if (i < nq)
                    exact = 0.0; // B does not read q'
                else
                    exact = dacc_dqd[(i - nq) * nq + (j - nq)];
                INFO("row " << i << ", variable " << j);
                CHECK(std::fabs(exact - fd) < 1e-7 * (1 + std::fabs(exact)));
            }
        }
    }
}
