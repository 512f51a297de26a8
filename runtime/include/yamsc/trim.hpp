#pragma once
// Trim: the operating point where the model is at rest in its own equations,
// F(q, q', u) = 0 for every DOF that is not held, by Newton's method with the
// generated Jacobian ∂F/∂q. Held DOFs keep their value and rate (a rotor
// spinning at a set speed); their residual is the generalized force that would
// hold them there (the torque a controller would have to apply).
//
// For a parked turbine this is the static equilibrium under gravity and
// constant loads (q' = 0, q'' = 0). With a spinning rotor held at its speed it
// is the quasi-static point at the given azimuth: the free DOFs' rates are
// kept as given (normally 0) and their accelerations vanish there.
//
// Steady operation adds inputs to the unknowns: the blade pitch or generator
// torque that holds a spinning rotor at its speed in a given wind. Each
// adjusted input balances one held DOF, whose residual must then vanish too
// (the controller's set point: no torque is left to hold the rotor).
#include "yamsc/model_view.hpp"

#include <string>
#include <vector>

namespace yamsc::runtime {

struct TrimSettings {
    /// Converged when max |F| over the free DOFs is at most this fraction of
    /// the generalized-force scale (max |F| at the start, at least 1).
    double relative_tolerance = 1e-10;
    /// Also converged when a Newton step moves no free DOF by more than this
    /// times max(1, max |q|): F is then at its floating-point floor.
    double step_tolerance = 1e-13;
    int max_iterations = 50;
    /// Load blocks with discrete states (unsteady airfoils, dynamic inflow):
    /// they are settled at the point, advanced in steps of `discrete_step` for
    /// `discrete_settle_time` as if time went on with the point standing still.
    /// Newton solves the quasi-steady equations (the blocks' states reset) plus
    /// the settled minus the quasi-steady forces of the last point (a defect
    /// correction), until a pass moves no unknown by more than
    /// `discrete_tolerance` times max(1, its size), at most
    /// `max_discrete_passes` passes.
    double discrete_step = 0.00625;   // [s]
    double discrete_settle_time = 10; // [s]
    double discrete_tolerance = 1e-9;
    int max_discrete_passes = 20;
};

/// Inputs trimmed with the DOFs, and the held DOFs whose residual they cancel
/// (as many of each).
struct TrimAdjustment {
    std::vector<int> inputs;   ///< indices into u
    std::vector<int> balanced; ///< indices of held DOFs
};

struct TrimResult {
    std::vector<double> q, qd;    ///< the point (held DOFs as given)
    std::vector<double> u;        ///< the inputs (adjusted ones trimmed)
    std::vector<double> residual; ///< F(q, q', u) for every DOF
    std::vector<bool> held;       ///< as given
    int iterations = 0;           ///< Newton steps taken
    int discrete_passes = 0;      ///< settling passes of the blocks' discrete states
    double max_free_residual = 0; ///< max |F| over the free and balanced DOFs
    double tolerance = 0;         ///< what max_free_residual had to reach
    bool converged = false;
};

/// Newton's method from (q0, q0') at inputs u and time t. Each step solves
/// J δ = -F over the free DOFs (and the adjusted inputs against the balanced
/// DOFs' residuals) with the minimum-norm solution (a complete
/// orthogonal decomposition), so that directions without stiffness (a free
/// rotor's azimuth) are left where they are, and is halved until |F| decreases.
/// The view needs forcing and jacobians. Throws std::invalid_argument for
/// wrong sizes or an adjustment that is not one input per held DOF; a point
/// that does not converge is returned with converged = false (the caller
/// reports the residual by DOF). With discrete block states (view.update_discrete)
/// the point is where they are steady too, and the blocks keep those states:
/// a linearization or a run that follows starts from them (TrimSettings).
TrimResult trim(const ModelView& view, const std::vector<double>& q0,
                const std::vector<double>& qd0, const std::vector<double>& u,
                const std::vector<bool>& held, double t = 0.0, const TrimSettings& settings = {},
                const TrimAdjustment& adjust = {});

} // namespace yamsc::runtime
