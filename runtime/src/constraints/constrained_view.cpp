// constrain(): the view whose rhs solves the KKT system of the constrained
// accelerations, with its exact Jacobian and the reactions and residuals as
// outputs.
#include "yamsc/constraints.hpp"

#include "rows.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace yamsc::runtime {

using constraints::Kkt;
using constraints::Matrix;
using constraints::Vector;

namespace {

std::size_t at(int i) {
    return static_cast<std::size_t>(i);
}

/// The lower half of rhs_jacobian: d(q'')/d[q, q'] (nq x 2nq) at the KKT point.
Eigen::MatrixXd acceleration_jacobian(const ModelView& v, const Kkt& k, double t, const double* q,
                                      const double* qd, const double* u) {
    const int nq = v.nq, nc = v.nc, nu = std::max(v.nu, 1);
    Matrix Fq(nq, nq), Fv(nq, nq), Fu(nq, nu);
    v.jacobians(t, q, qd, u, Fq.data(), Fv.data(), Fu.data());
    Matrix dBTl(nq, nq), dacc_q(nc, nq), dacc_v(nc, nq), dBTl_u(nq, nu), dacc_u(nc, nu);
    v.constraint_jacobians(t, q, qd, u, k.lambda.data(), k.qdd.data(), dBTl.data(), dacc_q.data(),
                           dacc_v.data(), dBTl_u.data(), dacc_u.data());
    const Matrix D = constraints::mass_action_jacobian(v, t, q, k.qdd.data(), u);
    Eigen::MatrixXd top(nq, 2 * nq), bottom(nc, 2 * nq);
    top << Fq - D + dBTl, Fv;
    bottom << -dacc_q, -dacc_v;
    return k.solve(top, bottom).topRows(nq);
}

struct Shared {
    ModelView base;
    ConstraintOptions options;
};

void append_rows(const ModelView& b, double t, const double* q, const double* qd, const double* u,
                 const Vector& lambda, double* y) {
    Vector phi, r;
    constraints::residuals(b, t, q, qd, u, phi, r);
    double* out = y + b.ny;
    for (int i = 0; i < b.nc; ++i) *out++ = lambda[i];
    for (int i = 0; i < b.nh; ++i) *out++ = phi[i];
    for (int i = 0; i < b.nc; ++i) *out++ = r[i];
    *out++ = b.nh ? phi.cwiseAbs().maxCoeff() : 0.0;
    *out = r.cwiseAbs().maxCoeff();
}

void project_state(const ModelView& b, const ConstraintOptions& o, double t, double* x,
                   const double* u);

} // namespace

void constrained_acceleration(const ModelView& base, double t, const double* q, const double* qd,
                              const double* u, double* qdd, double* lambda) {
    const Kkt k(base, t, q, qd, u);
    std::copy(k.qdd.data(), k.qdd.data() + base.nq, qdd);
    std::copy(k.lambda.data(), k.lambda.data() + base.nc, lambda);
}

ModelView constrain(const ModelView& view, const ConstraintOptions& options) {
    if (view.nc == 0) return view;
    constraints::require_rows(view, "constrain");
    if (!view.mass_matrix || !view.forcing)
        throw std::invalid_argument("constrain: the model was compiled without its mass_matrix "
                                    "or forcing routine");
    if (view.nz != 0)
        throw std::invalid_argument("constrain: close load blocks around the constrained view, "
                                    "not before");
    auto s = std::make_shared<const Shared>(Shared{view, options});
    ModelView v = view;
    const int nq = v.nq;
    // M stays (the tree's, for the reduced mass matrix); F and its Jacobians go:
    // the constrained q'' is not M^-1 F.
    v.forcing = nullptr;
    v.jacobians = nullptr;
    v.mass_action_jacobian = nullptr;
    v.rhs = [s, nq](double t, const double* x, const double* u, double* xdot) {
        const Kkt k(s->base, t, x, x + nq, u);
        std::copy(x + nq, x + 2 * nq, xdot);
        std::copy(k.qdd.data(), k.qdd.data() + nq, xdot + nq);
    };
    if (view.jacobians)
        v.rhs_jacobian = [s, nq](double t, const double* x, const double* u, double* J) {
            const Kkt k(s->base, t, x, x + nq, u);
            const Eigen::MatrixXd lower = acceleration_jacobian(s->base, k, t, x, x + nq, u);
            const int n = 2 * nq;
            std::fill(J, J + n * n, 0.0);
            for (int i = 0; i < nq; ++i) J[i * n + nq + i] = 1.0;
            for (int i = 0; i < nq; ++i)
                for (int j = 0; j < n; ++j) J[(nq + i) * n + j] = lower(i, j);
        };
    else
        v.rhs_jacobian = nullptr;
    for (int i = 0; i < v.nc; ++i) v.output_names.push_back("lambda:" + v.constraint_names[at(i)]);
    for (int i = 0; i < v.nh; ++i) v.output_names.push_back("phi:" + v.constraint_names[at(i)]);
    for (int i = 0; i < v.nc; ++i) v.output_names.push_back("r:" + v.constraint_names[at(i)]);
    v.output_names.emplace_back("constraint_position_error");
    v.output_names.emplace_back("constraint_velocity_error");
    v.ny = static_cast<int>(v.output_names.size());
    // The base's outputs at the constrained q'' (outputs that read q'' see it);
    // a base without outputs_from_qdd gives its outputs at its own q''.
    const auto outputs = [s](double t, const double* q, const double* qd, const double* u,
                             double* y) {
        const ModelView& b = s->base;
        const Kkt k(b, t, q, qd, u);
        if (b.ny > 0) {
            if (b.outputs_from_qdd)
                b.outputs_from_qdd(t, q, qd, k.qdd.data(), u, y);
            else
                b.outputs(t, q, qd, u, y);
        }
        append_rows(b, t, q, qd, u, k.lambda, y);
    };
    v.outputs = outputs;
    v.outputs_from_qdd = [outputs](double t, const double* q, const double* qd, const double*,
                                   const double* u, double* y) { outputs(t, q, qd, u, y); };
    if (options.project)
        v.project = [s](double t, double* x, const double* u) {
            project_state(s->base, s->options, t, x, u);
        };
    return v;
}

namespace {

void project_state(const ModelView& b, const ConstraintOptions& o, double t, double* x,
                   const double* u) {
    const int nq = b.nq;
    Vector phi, r;
    // q onto Phi = 0: Gauss-Newton with minimum-norm steps (Phi_q^+ Phi).
    for (int it = 0; b.nh > 0 && it < o.max_iterations; ++it) {
        constraints::residuals(b, t, x, x + nq, u, phi, r);
        if (phi.cwiseAbs().maxCoeff() <= o.position_tolerance) break;
        const Matrix H = constraints::matrix_b(b, t, x, u).topRows(b.nh);
        const Vector dq = -H.transpose() * (H * H.transpose()).ldlt().solve(phi);
        for (int i = 0; i < nq; ++i) x[i] += dq[i];
    }
    // q' onto r = 0: r is linear in q', one minimum-norm step.
    constraints::residuals(b, t, x, x + nq, u, phi, r);
    if (r.cwiseAbs().maxCoeff() <= o.velocity_tolerance) return;
    const Matrix B = constraints::matrix_b(b, t, x, u);
    const Vector dv = -B.transpose() * (B * B.transpose()).ldlt().solve(r);
    for (int i = 0; i < nq; ++i) x[nq + i] += dv[i];
}

} // namespace

ConstraintResiduals constraint_residual_norms(const ModelView& view, double t, const double* x,
                                              const double* u) {
    ConstraintResiduals out;
    if (view.nc == 0) return out;
    Vector phi, r;
    constraints::residuals(view, t, x, x + view.nq, u, phi, r);
    out.position = view.nh ? phi.cwiseAbs().maxCoeff() : 0.0;
    out.velocity = r.cwiseAbs().maxCoeff();
    return out;
}

} // namespace yamsc::runtime
