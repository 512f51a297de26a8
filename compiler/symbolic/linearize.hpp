#pragma once
// Symbolic linearization (paper section 2.5, eq. 23-25) about an operating point
// (q0, q0', u0) that may depend on the parameters: the linear matrices are then
// functions of the parameters only, an LPV model.
//
//   M0 δq'' + C0 δq' + K0 δq = Q0 δu,
//   M0 = M|0,  C0 = -∂F/∂q'|0,  K0 = -∂F/∂q|0 + ∂(M a)/∂q|0 with a = q''0,  Q0 = ∂F/∂u|0.
//
// The accelerations of the operating point are the solved ones, q''0 = M0⁻¹ F0,
// not zero: then A = [0 I; -M0⁻¹K0 -M0⁻¹C0] is exactly the Jacobian of the
// first-order system x' = [q', M⁻¹F] at any point, and at an equilibrium
// (F0 = 0) both choices agree. The matrices themselves are built from the
// Jacobians where they are used: as code by codegen/linear_routines.cpp (from
// the passes on the IR, passes/linearize.cpp), as formulas by
// codegen/emit_latex.cpp.
#include "model/model.hpp"
#include "symbolic/equations.hpp"

namespace yamsc::symbolic {

/// The operating point as expressions of the parameters: one per DOF, rate and
/// input channel. `declared` is false when the model has no `linearize` block (all 0).
struct OperatingPoint {
    Row q, qd, u;
    bool declared = false;
};

/// The model's `linearize` block over the symbols of `eq` (derived from `m`).
OperatingPoint operating_point(const model::Model& m, const Equations& eq);

} // namespace yamsc::symbolic
