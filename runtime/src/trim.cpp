#include "yamsc/trim.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::runtime {

namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// The generalized forces of the view at (q, u), q' fixed.
class Forces {
public:
    Forces(const ModelView& v, const std::vector<double>& qd, double t)
        : v_(v), qd_(qd), t_(t), F_(static_cast<std::size_t>(v.nq)), dq_(v.nq, v.nq),
          dqd_(v.nq, v.nq), du_(v.nq, std::max(v.nu, 1)) {}

    const std::vector<double>& at(const std::vector<double>& q, const std::vector<double>& u) {
        v_.forcing(t_, q.data(), qd_.data(), inputs(u), F_.data());
        if (!offset_.empty())
            for (std::size_t i = 0; i < F_.size(); ++i) F_[i] += offset_[i];
        return F_;
    }
    /// Added to every F from now on (constant in q and u).
    void set_offset(std::vector<double> offset) { offset_ = std::move(offset); }
    /// ∂F/∂q and ∂F/∂u at (q, u), in dq() and du().
    void differentiate(const std::vector<double>& q, const std::vector<double>& u) {
        v_.jacobians(t_, q.data(), qd_.data(), inputs(u), dq_.data(), dqd_.data(), du_.data());
    }
    const RowMajor& dq() const { return dq_; }
    const RowMajor& du() const { return du_; }

private:
    static const double* inputs(const std::vector<double>& u) {
        return u.empty() ? nullptr : u.data();
    }
    const ModelView& v_;
    const std::vector<double>& qd_;
    double t_;
    std::vector<double> F_, offset_;
    RowMajor dq_, dqd_, du_;
};

/// The unknowns of the trim (free DOFs, then adjusted inputs) and the
/// residual rows that must vanish (free DOFs, then balanced DOFs).
struct Unknowns {
    std::vector<int> free, inputs, rows;

    double max_residual(const std::vector<double>& F) const {
        double m = 0;
        for (int i : rows) m = std::max(m, std::fabs(F[static_cast<std::size_t>(i)]));
        return m;
    }
    Eigen::Index size() const { return static_cast<Eigen::Index>(free.size() + inputs.size()); }
    /// The current value of unknown k.
    double value(Eigen::Index k, const std::vector<double>& q, const std::vector<double>& u) const {
        const auto nf = static_cast<Eigen::Index>(free.size());
        return k < nf ? q[static_cast<std::size_t>(free[static_cast<std::size_t>(k)])]
                      : u[static_cast<std::size_t>(inputs[static_cast<std::size_t>(k - nf)])];
    }
    /// (q, u) moved by scale * step from (q0, u0).
    void move(const std::vector<double>& q0, const std::vector<double>& u0,
              const Eigen::VectorXd& step, double scale, std::vector<double>& q,
              std::vector<double>& u) const {
        q = q0;
        u = u0;
        for (std::size_t a = 0; a < free.size(); ++a)
            q[static_cast<std::size_t>(free[a])] += scale * step(static_cast<Eigen::Index>(a));
        for (std::size_t a = 0; a < inputs.size(); ++a)
            u[static_cast<std::size_t>(inputs[a])] +=
                scale * step(static_cast<Eigen::Index>(free.size() + a));
    }
};

Unknowns unknowns_of(const ModelView& view, const std::vector<bool>& held,
                     const TrimAdjustment& adjust) {
    Unknowns x;
    for (std::size_t i = 0; i < held.size(); ++i)
        if (!held[i]) x.free.push_back(static_cast<int>(i));
    x.rows = x.free;
    if (adjust.inputs.size() != adjust.balanced.size())
        throw std::invalid_argument("trim: each adjusted input must balance one held DOF (" +
                                    std::to_string(adjust.inputs.size()) + " inputs, " +
                                    std::to_string(adjust.balanced.size()) + " DOFs)");
    for (int k : adjust.inputs) {
        if (k < 0 || k >= view.nu) throw std::invalid_argument("trim: no such input to adjust");
        if (std::count(adjust.inputs.begin(), adjust.inputs.end(), k) > 1)
            throw std::invalid_argument("trim: an input is adjusted twice");
    }
    for (int i : adjust.balanced) {
        if (i < 0 || i >= view.nq || !held[static_cast<std::size_t>(i)])
            throw std::invalid_argument("trim: only a held DOF can be balanced by an input");
        if (std::count(adjust.balanced.begin(), adjust.balanced.end(), i) > 1)
            throw std::invalid_argument("trim: a DOF is balanced twice");
    }
    x.inputs = adjust.inputs;
    x.rows.insert(x.rows.end(), adjust.balanced.begin(), adjust.balanced.end());
    return x;
}

/// Newton's method on `x`'s unknowns from r's point (r.tolerance set).
void newton(const Unknowns& x, Forces& forces, const TrimSettings& settings, TrimResult& r);

/// The view's discrete states from a run's start, advanced at r's point, which
/// stands still.
void settle_discrete_states(const ModelView& view, const TrimResult& r, double t,
                            const TrimSettings& settings) {
    view.reset_discrete();
    std::vector<double> state(r.q);
    state.insert(state.end(), r.qd.begin(), r.qd.end());
    const double* u = r.u.empty() ? nullptr : r.u.data();
    const auto steps =
        static_cast<long>(std::ceil(settings.discrete_settle_time / settings.discrete_step));
    for (long k = 0; k < steps; ++k)
        view.update_discrete(t, state.data(), u, t + settings.discrete_step, state.data(), u);
}

/// The largest change of an unknown from `a` to `b`, relative to max(1, its size).
double largest_change(const Unknowns& x, const TrimResult& a, const TrimResult& b) {
    double change = 0;
    for (Eigen::Index k = 0; k < x.size(); ++k) {
        const double after = x.value(k, b.q, b.u);
        change = std::max(change, std::fabs(after - x.value(k, a.q, a.u)) /
                                      std::max(1.0, std::fabs(after)));
    }
    return change;
}

/// The point where the blocks' discrete states are steady as well. Their settled
/// forces are not smooth enough in (q, u) for Newton with the states held (a
/// held unsteady airfoil answers a new angle of attack with its transient), so
/// Newton solves the quasi-steady forces plus the defect the settled states add
/// at the last point; the defect varies slowly with the point.
void trim_with_discrete_states(const ModelView& view, const Unknowns& x, Forces& forces, double t,
                               const TrimSettings& settings, TrimResult& r) {
    bool settled = false;
    while (r.converged && !settled && r.discrete_passes < settings.max_discrete_passes) {
        settle_discrete_states(view, r, t, settings);
        forces.set_offset({});
        std::vector<double> defect = forces.at(r.q, r.u);
        view.reset_discrete();
        const std::vector<double>& quasi_steady = forces.at(r.q, r.u);
        for (std::size_t i = 0; i < defect.size(); ++i) defect[i] -= quasi_steady[i];
        forces.set_offset(std::move(defect));
        const TrimResult before = r;
        ++r.discrete_passes;
        newton(x, forces, settings, r);
        settled = largest_change(x, before, r) <= settings.discrete_tolerance;
    }
    // The blocks keep the states of the point; its residual is theirs.
    settle_discrete_states(view, r, t, settings);
    forces.set_offset({});
    r.residual = forces.at(r.q, r.u);
    r.max_free_residual = x.max_residual(r.residual);
    r.converged = r.converged && settled;
}

} // namespace

TrimResult trim(const ModelView& view, const std::vector<double>& q0,
                const std::vector<double>& qd0, const std::vector<double>& u0,
                const std::vector<bool>& held, double t, const TrimSettings& settings,
                const TrimAdjustment& adjust) {
    const auto nq = static_cast<std::size_t>(view.nq);
    if (q0.size() != nq || qd0.size() != nq || held.size() != nq ||
        u0.size() != static_cast<std::size_t>(view.nu))
        throw std::invalid_argument("trim: the point has the wrong size");
    if (nq == 0)
        throw std::invalid_argument(
            "trim: the model has no DOF (its motion is all prescribed): there is nothing to trim");
    if (!view.forcing || !view.jacobians)
        throw std::invalid_argument(
            "trim: the model was compiled without its forcing or jacobians routine");
    const Unknowns x = unknowns_of(view, held, adjust);

    TrimResult r;
    r.q = q0;
    r.qd = qd0;
    r.u = u0;
    r.held = held;
    Forces forces(view, r.qd, t);
    r.tolerance = settings.relative_tolerance * std::max(1.0, x.max_residual(forces.at(r.q, r.u)));
    if (view.update_discrete && view.reset_discrete) view.reset_discrete();
    newton(x, forces, settings, r);
    if (view.update_discrete && view.reset_discrete)
        trim_with_discrete_states(view, x, forces, t, settings, r);
    return r;
}

namespace {

void newton(const Unknowns& x, Forces& forces, const TrimSettings& settings, TrimResult& r) {
    double norm = x.max_residual(forces.at(r.q, r.u));
    const int first = r.iterations;
    const Eigen::Index n = x.size();
    const auto m = static_cast<Eigen::Index>(x.rows.size());
    bool at_round_off = false;
    std::vector<double> trial_q, trial_u;
    while (norm > r.tolerance && r.iterations - first < settings.max_iterations) {
        const std::vector<double> F = forces.at(r.q, r.u);
        forces.differentiate(r.q, r.u);
        Eigen::MatrixXd J(m, n);
        Eigen::VectorXd rhs(m);
        for (Eigen::Index a = 0; a < m; ++a) {
            const int row = x.rows[static_cast<std::size_t>(a)];
            rhs(a) = -F[static_cast<std::size_t>(row)];
            for (std::size_t b = 0; b < x.free.size(); ++b)
                J(a, static_cast<Eigen::Index>(b)) = forces.dq()(row, x.free[b]);
            for (std::size_t b = 0; b < x.inputs.size(); ++b)
                J(a, static_cast<Eigen::Index>(x.free.size() + b)) = forces.du()(row, x.inputs[b]);
        }
        const Eigen::VectorXd step = J.completeOrthogonalDecomposition().solve(rhs);
        if (!step.allFinite()) break;
        // The largest step relative to its unknown's size (at least 1).
        double relative_step = 0;
        for (Eigen::Index k = 0; k < n; ++k)
            relative_step = std::max(
                relative_step, std::fabs(step(k)) / std::max(1.0, std::fabs(x.value(k, r.q, r.u))));
        // A step at round-off of the unknowns: F is as small as it gets in floating point.
        if (relative_step <= settings.step_tolerance) {
            // Either F is at its floating-point floor (J step = -F holds), or
            // part of F lies where J has no stiffness: no equilibrium.
            at_round_off = (J * step - rhs).lpNorm<Eigen::Infinity>() <= r.tolerance;
            break;
        }
        ++r.iterations;
        // Halve the step until |F| decreases (at most 30 times).
        bool improved = false;
        for (double scale = 1.0; scale > 1e-9; scale *= 0.5) {
            x.move(r.q, r.u, step, scale, trial_q, trial_u);
            const double trial_norm = x.max_residual(forces.at(trial_q, trial_u));
            if (std::isfinite(trial_norm) && trial_norm < norm) {
                r.q = trial_q;
                r.u = trial_u;
                norm = trial_norm;
                improved = true;
                break;
            }
        }
        if (!improved) {
            // No decrease: F is noise (a small step that solves the linear
            // problem), or this is a minimum of |F| that is not a root.
            at_round_off =
                relative_step <= 1e-8 && (J * step - rhs).lpNorm<Eigen::Infinity>() <= r.tolerance;
            break;
        }
    }
    r.residual = forces.at(r.q, r.u);
    r.max_free_residual = x.max_residual(r.residual);
    r.converged = r.max_free_residual <= r.tolerance || at_round_off;
}

} // namespace

} // namespace yamsc::runtime
