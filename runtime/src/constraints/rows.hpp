#pragma once
// The constraint rows of a view as Eigen matrices, and the KKT system of the
// constrained accelerations. Internal to the runtime's constraints.
#include "yamsc/constraints.hpp"
#include "yamsc/model_view.hpp"

#include <Eigen/Dense>

#include <vector>

namespace yamsc::runtime::constraints {

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using Vector = Eigen::VectorXd;

/// A null pointer for an empty input vector (the generated routines never read it).
inline const double* inputs(const std::vector<double>& u) {
    return u.empty() ? nullptr : u.data();
}

/// Throws std::invalid_argument unless the view has the routines `what` needs.
void require_rows(const ModelView& v, const char* what);

/// B (nc x nq) at (t, q, u).
Matrix matrix_b(const ModelView& v, double t, const double* q, const double* u);

/// Phi (nh) and r (nc) at (t, q, q', u).
void residuals(const ModelView& v, double t, const double* q, const double* qd, const double* u,
               Vector& phi, Vector& r);

/// d(M a)/dq at fixed a: the view's mass_action_jacobian, or central differences
/// of mass_matrix.
Matrix mass_action_jacobian(const ModelView& v, double t, const double* q, const double* a,
                            const double* u);

/// The KKT system [M -B^T; B 0] [q''; lambda] = [F; -gamma] at one point, kept
/// factored for the Jacobian's right-hand sides.
struct Kkt {
    int nq = 0, nc = 0;
    Matrix M, B;
    Vector F, gamma, qdd, lambda;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;

    /// Builds and solves at the point; throws ConstraintError (singular) when
    /// the KKT matrix is singular, naming the time.
    Kkt(const ModelView& v, double t, const double* q, const double* qd, const double* u);
    /// [dq''; dlambda] for right-hand sides [top (nq rows); bottom (nc rows)].
    Eigen::MatrixXd solve(const Eigen::MatrixXd& top, const Eigen::MatrixXd& bottom) const;
};

/// Rows of B whose columns are `columns`, as a dense block (rows x columns.size()).
Matrix columns_of(const Matrix& m, const std::vector<int>& columns);

/// The basis of the tangent space at x (see ReducedLinearModel): T, nx x ns.
Matrix tangent_basis(const ModelView& v, double t, const double* x, const double* u,
                     const DependentChoice& choice);

/// Newton on Phi over `dofs` (the dependent coordinates), halving steps that do
/// not reduce max |Phi|; x = [q, q', ...] changed in place. Returns the
/// iterations; throws ConstraintError (inconsistent, the row of the largest
/// residual) when max |Phi| does not reach options.position_tolerance.
int solve_positions(const ModelView& v, double t, double* x, const double* u,
                    const std::vector<int>& dofs, const ConstraintOptions& options);
/// r = 0 over the dependent speeds `dofs` (one linear solve).
void solve_speeds(const ModelView& v, double t, double* x, const double* u,
                  const std::vector<int>& dofs);

} // namespace yamsc::runtime::constraints
