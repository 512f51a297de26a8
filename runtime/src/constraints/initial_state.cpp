// The consistent start: Newton on Phi over the dependent coordinates, then
// r = 0 over the dependent speeds.
#include "yamsc/constraints.hpp"

#include "rows.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yamsc::runtime {

using constraints::Matrix;
using constraints::Vector;

namespace {
std::size_t at(int i) {
    return static_cast<std::size_t>(i);
}
} // namespace

/// Newton on Phi over `dofs` (nh of them), halving steps that do not reduce
/// max |Phi|. Returns the iterations; throws ConstraintError (inconsistent).
int constraints::solve_positions(const ModelView& v, double t, double* x, const double* u,
                                 const std::vector<int>& dofs, const ConstraintOptions& o) {
    const int nq = v.nq;
    Vector phi, r;
    constraints::residuals(v, t, x, x + nq, u, phi, r);
    double size = phi.size() ? phi.cwiseAbs().maxCoeff() : 0.0;
    int it = 0;
    for (; size > o.position_tolerance && it < o.max_iterations; ++it) {
        const Matrix H = constraints::columns_of(constraints::matrix_b(v, t, x, u), dofs);
        const Vector step = H.topRows(v.nh).fullPivLu().solve(-phi);
        std::vector<double> start(x, x + nq);
        double scale = 1.0;
        double trial = size;
        for (int halving = 0; halving < 30; ++halving, scale *= 0.5) {
            for (std::size_t k = 0; k < dofs.size(); ++k)
                x[dofs[k]] = start[at(dofs[k])] + scale * step[static_cast<Eigen::Index>(k)];
            constraints::residuals(v, t, x, x + nq, u, phi, r);
            trial = phi.cwiseAbs().maxCoeff();
            if (std::isfinite(trial) && trial < size) break;
        }
        if (!(std::isfinite(trial) && trial < size)) break;
        size = trial;
    }
    if (!(size <= o.position_tolerance)) {
        Eigen::Index worst = 0;
        phi.cwiseAbs().maxCoeff(&worst);
        const int row = static_cast<int>(worst);
        std::ostringstream msg;
        msg << "constraint row '" << v.constraint_names[at(row)] << "'";
        if (at(row) < v.constraint_sources.size() && !v.constraint_sources[at(row)].empty())
            msg << " (" << v.constraint_sources[at(row)] << ")";
        msg << " cannot be satisfied from the initial state: Newton's method over the dependent "
               "coordinates stopped with residual "
            << phi[worst] << " after " << it << " iterations (inconsistent constraints?)";
        throw ConstraintError(ConstraintErrorKind::inconsistent, row, {}, msg.str());
    }
    return it;
}

void constraints::solve_speeds(const ModelView& v, double t, double* x, const double* u,
                               const std::vector<int>& dofs) {
    // r = B q' + c is linear in q': one solve over the dependent speeds.
    Vector phi, r;
    constraints::residuals(v, t, x, x + v.nq, u, phi, r);
    const Matrix Bd = constraints::columns_of(constraints::matrix_b(v, t, x, u), dofs);
    const Vector dv = Bd.fullPivLu().solve(-r);
    for (std::size_t k = 0; k < dofs.size(); ++k)
        x[v.nq + dofs[k]] += dv[static_cast<Eigen::Index>(k)];
}

ConsistentState consistent_initial_state(const ModelView& v, double t,
                                         const std::vector<double>& x0,
                                         const std::vector<double>& u, const ConstraintOptions& o) {
    if (static_cast<int>(x0.size()) != v.nx())
        throw std::invalid_argument("consistent_initial_state: the state has the wrong size");
    ConsistentState s;
    s.x = x0;
    if (v.nc == 0) return s;
    const double* up = constraints::inputs(u);
    double* x = s.x.data();
    s.choice = choose_dependent(v, t, x, up, o);
    s.iterations = constraints::solve_positions(v, t, x, up, s.choice.coordinates, o);
    constraints::solve_speeds(v, t, x, up, s.choice.speeds);
    return s;
}

} // namespace yamsc::runtime
