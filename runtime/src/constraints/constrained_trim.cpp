// trim on a constrained view: Newton over the independent coordinates on the
// independent speeds' accelerations, the dependent ones following the rows.
#include "yamsc/constraints.hpp"

#include "rows.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::runtime {

using constraints::Matrix;
using constraints::Vector;

namespace {

std::size_t at(int i) {
    return static_cast<std::size_t>(i);
}

/// The independent speeds' accelerations at x.
Vector residual_at(const ModelView& v, double t, const std::vector<double>& x, const double* u,
                   const DependentChoice& c) {
    std::vector<double> xdot(x.size());
    v.rhs(t, x.data(), u, xdot.data());
    Vector r(static_cast<Eigen::Index>(c.independent_speeds.size()));
    for (std::size_t k = 0; k < c.independent_speeds.size(); ++k)
        r[static_cast<Eigen::Index>(k)] = xdot[at(v.nq + c.independent_speeds[k])];
    return r;
}

} // namespace

ConstrainedTrimResult trim_constrained(const ModelView& v, const std::vector<double>& x0,
                                       const std::vector<double>& u0, double t, double tolerance,
                                       int max_iterations, const ConstraintOptions& options) {
    if (!v.rhs) throw std::invalid_argument("trim: the model view has no right-hand side");
    ConsistentState start = consistent_initial_state(v, t, x0, u0, options);
    const double* u = constraints::inputs(u0);
    ConstrainedTrimResult out;
    out.choice = start.choice;
    const DependentChoice& c = out.choice;
    std::vector<double> x = start.x;
    Vector r = residual_at(v, t, x, u, c);
    const double scale = std::max(1.0, r.size() ? r.cwiseAbs().maxCoeff() : 0.0);
    const int mq = static_cast<int>(c.independent_coordinates.size());
    const auto size = [](const Vector& a) { return a.size() ? a.cwiseAbs().maxCoeff() : 0.0; };
    while (size(r) > tolerance * scale && out.iterations < max_iterations) {
        const Matrix T = constraints::tangent_basis(v, t, x.data(), u, c);
        const std::vector<double> Jv = state_matrix_from_view(v, x, u0, t);
        const Eigen::Map<const Matrix> J(Jv.data(), v.nx(), v.nx());
        Matrix Jr(r.size(), mq);
        for (Eigen::Index k = 0; k < r.size(); ++k)
            Jr.row(k) =
                J.row(v.nq + c.independent_speeds[at(static_cast<int>(k))]) * T.leftCols(mq);
        const Vector step = Eigen::MatrixXd(Jr).completeOrthogonalDecomposition().solve(-r);
        const std::vector<double> from = x;
        double scale_step = 1.0;
        Vector trial;
        for (int halving = 0; halving < 20; ++halving, scale_step *= 0.5) {
            x = from;
            for (int k = 0; k < mq; ++k)
                x[at(c.independent_coordinates[at(k)])] += scale_step * step[k];
            constraints::solve_positions(v, t, x.data(), u, c.coordinates, options);
            constraints::solve_speeds(v, t, x.data(), u, c.speeds);
            trial = residual_at(v, t, x, u, c);
            if (size(trial) < size(r)) break;
        }
        ++out.iterations;
        if (!(size(trial) < size(r))) {
            x = from;
            break;
        }
        r = trial;
    }
    out.x = x;
    out.residual.assign(r.data(), r.data() + r.size());
    out.max_residual = size(r);
    out.converged = out.max_residual <= tolerance * scale;
    return out;
}

} // namespace yamsc::runtime
