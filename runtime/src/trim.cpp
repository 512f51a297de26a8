#include "yamsc/trim.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::runtime {

namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// The generalized forces of the view at q (q' and u fixed).
class Forces {
public:
    Forces(const ModelView& v, const std::vector<double>& qd, const std::vector<double>& u,
           double t)
        : v_(v), qd_(qd), u_(u), t_(t), F_(static_cast<std::size_t>(v.nq)), dq_(v.nq, v.nq),
          dqd_(v.nq, v.nq), du_(v.nq, std::max(v.nu, 1)) {}

    const std::vector<double>& at(const std::vector<double>& q) {
        v_.forcing(t_, q.data(), qd_.data(), inputs(), F_.data());
        return F_;
    }
    const RowMajor& jacobian(const std::vector<double>& q) {
        v_.jacobians(t_, q.data(), qd_.data(), inputs(), dq_.data(), dqd_.data(), du_.data());
        return dq_;
    }

private:
    const double* inputs() const { return u_.empty() ? nullptr : u_.data(); }
    const ModelView& v_;
    const std::vector<double>& qd_;
    const std::vector<double>& u_;
    double t_;
    std::vector<double> F_;
    RowMajor dq_, dqd_, du_;
};

double max_free(const std::vector<double>& F, const std::vector<int>& free) {
    double m = 0;
    for (int i : free) m = std::max(m, std::fabs(F[static_cast<std::size_t>(i)]));
    return m;
}

} // namespace

TrimResult trim(const ModelView& view, const std::vector<double>& q0,
                const std::vector<double>& qd0, const std::vector<double>& u,
                const std::vector<bool>& held, double t, const TrimSettings& settings) {
    const auto nq = static_cast<std::size_t>(view.nq);
    if (q0.size() != nq || qd0.size() != nq || held.size() != nq ||
        u.size() != static_cast<std::size_t>(view.nu))
        throw std::invalid_argument("trim: the point has the wrong size");
    if (!view.forcing || !view.jacobians)
        throw std::invalid_argument(
            "trim: the model was compiled without its forcing or jacobians routine");
    std::vector<int> free;
    for (std::size_t i = 0; i < nq; ++i)
        if (!held[i]) free.push_back(static_cast<int>(i));

    TrimResult r;
    r.q = q0;
    r.qd = qd0;
    r.held = held;
    Forces forces(view, r.qd, u, t);
    double norm = max_free(forces.at(r.q), free);
    r.tolerance = settings.relative_tolerance * std::max(1.0, norm);
    const auto n = static_cast<Eigen::Index>(free.size());
    bool at_round_off = false;
    while (norm > r.tolerance && r.iterations < settings.max_iterations) {
        const std::vector<double> F = forces.at(r.q);
        const RowMajor& dF = forces.jacobian(r.q);
        Eigen::MatrixXd J(n, n);
        Eigen::VectorXd rhs(n);
        for (Eigen::Index a = 0; a < n; ++a) {
            rhs(a) = -F[static_cast<std::size_t>(free[a])];
            for (Eigen::Index b = 0; b < n; ++b) J(a, b) = dF(free[a], free[b]);
        }
        const Eigen::VectorXd step = J.completeOrthogonalDecomposition().solve(rhs);
        if (!step.allFinite()) break;
        double q_scale = 1.0;
        for (int i : free) q_scale = std::max(q_scale, std::fabs(r.q[static_cast<std::size_t>(i)]));
        // A step at round-off of q: F is as small as it gets in floating point.
        if (step.lpNorm<Eigen::Infinity>() <= settings.step_tolerance * q_scale) {
            // Either F is at its floating-point floor (J step = -F holds), or
            // part of F lies where J has no stiffness: no equilibrium.
            at_round_off = (J * step - rhs).lpNorm<Eigen::Infinity>() <= r.tolerance;
            break;
        }
        ++r.iterations;
        // Halve the step until |F| decreases (at most 30 times).
        bool improved = false;
        std::vector<double> trial = r.q;
        for (double scale = 1.0; scale > 1e-9; scale *= 0.5) {
            for (Eigen::Index a = 0; a < n; ++a)
                trial[static_cast<std::size_t>(free[a])] =
                    r.q[static_cast<std::size_t>(free[a])] + scale * step(a);
            const double trial_norm = max_free(forces.at(trial), free);
            if (std::isfinite(trial_norm) && trial_norm < norm) {
                r.q = trial;
                norm = trial_norm;
                improved = true;
                break;
            }
        }
        if (!improved) {
            // No decrease: F is noise (a small step that solves the linear
            // problem), or this is a minimum of |F| that is not a root.
            at_round_off = step.lpNorm<Eigen::Infinity>() <= 1e-8 * q_scale &&
                           (J * step - rhs).lpNorm<Eigen::Infinity>() <= r.tolerance;
            break;
        }
    }
    r.residual = forces.at(r.q);
    r.max_free_residual = max_free(r.residual, free);
    r.converged = r.max_free_residual <= r.tolerance || at_round_off;
    return r;
}

} // namespace yamsc::runtime
