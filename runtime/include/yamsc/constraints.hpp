#pragma once
// Constrained models (docs/constraints.md). A view with constraint rows
// (ModelView::nc > 0) moves as the index-1 system
//
//   M q'' - B^T lambda = F,   B q'' = -gamma,
//
// solved per evaluation; after each accepted step the integrators project the
// state back onto Phi = 0 and r = 0 (ModelView::project). The start is made
// consistent by Newton's method over the dependent coordinates, chosen at the
// initial state (the rows' named DOFs first, the rest by QR with column
// pivoting of B). `lin` and `trim` work in the independent coordinates.
#include "yamsc/modal.hpp"
#include "yamsc/model_view.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace yamsc::runtime {

enum class ConstraintErrorKind {
    redundant,    ///< B is rank deficient at the initial state: the row depends on others
    inconsistent, ///< Phi cannot be driven to 0 from the initial state
    singular      ///< a named dependent DOF cannot be solved for, or M q'' = F + B^T lambda is
                  ///< singular
};

/// A user error in the constraints, found at run time. row() is the row index
/// (into constraint_names and constraint_sources), or -1 when no row is to
/// blame; related() the rows it depends on (redundant rows).
class ConstraintError : public std::runtime_error {
public:
    ConstraintError(ConstraintErrorKind kind, int row, std::vector<int> related,
                    const std::string& message)
        : std::runtime_error(message), kind_(kind), row_(row), related_(std::move(related)) {}
    ConstraintErrorKind kind() const { return kind_; }
    int row() const { return row_; }
    const std::vector<int>& related() const { return related_; }

private:
    ConstraintErrorKind kind_;
    int row_;
    std::vector<int> related_;
};

struct ConstraintOptions {
    /// Newton on Phi (initial state) and the projection stop at max |Phi| <= this.
    double position_tolerance = 1e-12;
    /// The velocity projection stops at max |r| <= this.
    double velocity_tolerance = 1e-12;
    int max_iterations = 50;
    /// Pivots of a QR below this fraction of the largest one are zero (rank).
    double rank_tolerance = 1e-9;
    /// Set ModelView::project on the constrained view (sim keeps the constraints).
    bool project = true;
};

/// Which DOFs the constraints make dependent. coordinates: one per holonomic
/// row (nh); speeds: one per row (nc), the dependent coordinates' speeds first.
struct DependentChoice {
    std::vector<int> coordinates, speeds;
    std::vector<int> independent_coordinates, independent_speeds;
    /// Per DOF: named dependent by a row (constraint_dependent), not chosen by QR.
    std::vector<bool> named;
};

/// The choice at state x = [q, q'] (2 nq values) and inputs u. Throws
/// ConstraintError: redundant rows (naming the first row that depends on the
/// rows before it), a DOF named dependent by two rows or one that cannot be
/// solved for (singular).
DependentChoice choose_dependent(const ModelView& view, double t, const double* x, const double* u,
                                 const ConstraintOptions& options = {});

/// One line per set: "dependent coordinates: a (named), b; independent: c; ..."
/// (what `sim -v` prints).
std::string describe_choice(const ModelView& view, const DependentChoice& choice);

struct ConsistentState {
    std::vector<double> x; ///< [q, q'] (and any block states, unchanged)
    DependentChoice choice;
    int iterations = 0; ///< Newton steps on Phi
};

/// x0 moved onto the constraints: Newton on Phi over the dependent coordinates
/// from x0's q (the independent ones keep their values), then r = 0 over the
/// dependent speeds. Throws ConstraintError (choose_dependent's, and
/// inconsistent naming the row with the largest residual when Newton fails).
ConsistentState consistent_initial_state(const ModelView& view, double t,
                                         const std::vector<double>& x0,
                                         const std::vector<double>& u,
                                         const ConstraintOptions& options = {});

/// The norms of the residuals at a state: max |Phi| and max |r|.
struct ConstraintResiduals {
    double position = 0, velocity = 0;
};
ConstraintResiduals constraint_residual_norms(const ModelView& view, double t, const double* x,
                                              const double* u);

/// The view that moves with the constraints: rhs gives the constrained q'',
/// rhs_jacobian is exact (d(M a)/dq from ModelView::mass_action_jacobian, or
/// central differences of mass_matrix without it), outputs are the base's at the
/// constrained q'' followed by `lambda:ROW` (nc), `phi:ROW` (nh), `r:ROW` (nc),
/// `constraint_position_error` and `constraint_velocity_error` (max |Phi|, max
/// |r|). It keeps the constraint rows and, with options.project, sets
/// ModelView::project. forcing and jacobians are cleared (the constrained
/// accelerations are not M^-1 F; load blocks closed around the view then take
/// their loads' effect on q'' by central differences of rhs); mass_matrix stays. A view without
/// constraints is returned unchanged. Throws std::invalid_argument when the view lacks mass_matrix,
/// forcing or a constraint routine; evaluating it throws ConstraintError (singular) when the KKT
/// matrix is singular.
ModelView constrain(const ModelView& view, const ConstraintOptions& options = {});

/// The constrained q'' and lambda at a point (both views: the base one).
void constrained_acceleration(const ModelView& base, double t, const double* q, const double* qd,
                              const double* u, double* qdd, double* lambda);

/// The linear model on the constraint manifold, in the independent coordinates
/// and speeds s = [dq_i, dq'_i, z]: x - x0 = T s with dq = T_q dq_i (the null
/// space of Phi_q solved for the dependent coordinates) and dq' from
/// B dq' + (dr/dq) dq = 0 solved for the dependent speeds; A = P J T, B = P Ju,
/// P picking the independent rows (P T = I).
struct ReducedLinearModel {
    DependentChoice choice;
    int n_coordinates = 0, n_speeds = 0, nz = 0, nu = 0;
    std::vector<std::string> state_names; ///< ns: coordinates, speeds (with '), block states
    std::vector<double> T;                ///< nx x ns, row-major
    std::vector<double> A, B;             ///< ns x ns, ns x nu
    std::vector<Mode> modes;              ///< shapes in all nq coordinates (T's q rows)
    /// Holonomic only and no block states: M, C, K in the independent coordinates
    /// (M = T_q^T M T_q; C, K = -M times A's lower blocks).
    bool second_order = false;
    std::vector<double> M, C, K; ///< n_coordinates^2
};

/// About x0 (consistent: see consistent_initial_state), u0, t0 of a constrained
/// view (constrain(), possibly with blocks closed around it).
ReducedLinearModel reduced_linear_model(const ModelView& constrained, const std::vector<double>& x0,
                                        const std::vector<double>& u0, double t0 = 0.0,
                                        const ConstraintOptions& options = {});

struct ConstrainedTrimResult {
    std::vector<double> x; ///< the point, on the constraints
    DependentChoice choice;
    std::vector<double> residual; ///< the independent speeds' accelerations
    double max_residual = 0;
    int iterations = 0;
    bool converged = false;
};

/// The equilibrium (steady motion) of a constrained view near x0: Newton over
/// the independent coordinates on the independent speeds' accelerations (the
/// speeds held as given, made consistent), each step followed by the
/// dependent coordinates' Newton; minimum-norm steps.
ConstrainedTrimResult trim_constrained(const ModelView& constrained, const std::vector<double>& x0,
                                       const std::vector<double>& u, double t = 0.0,
                                       double tolerance = 1e-10, int max_iterations = 50,
                                       const ConstraintOptions& options = {});

} // namespace yamsc::runtime
