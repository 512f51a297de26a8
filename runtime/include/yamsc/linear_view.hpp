#pragma once
// The linear model of a view about an operating point (x0, u0, t0), as a view
// itself, so that the same integrators, CSV writers and comparisons run it:
//
//   x' = f(x0, u0, t0) + A (x - x0) + B (u - u0),   A = df/dx, B = df/du at the point.
//
// This is the first-order Taylor expansion of the nonlinear system x' = f(x, u, t)
// (paper eq. 23-25 in first-order form). It keeps the constant f(x0, u0, t0), so a
// point that is not an equilibrium (a rotor turning at the operating speed, gravity
// acting on an offset mass) is linearised about, not forced to, rest.
#include "yamsc/model_view.hpp"

#include <vector>

namespace yamsc::runtime {

/// The linearised system: A (2nq x 2nq) and B (2nq x nu), row-major, and the point.
struct LinearSystem {
    int nq = 0, nu = 0;
    std::vector<double> x0, u0, f0; ///< the point and f(x0, u0, t0)
    std::vector<double> A, B;
    double t0 = 0.0;
};

/// A and B of `view` at (x0, u0, t0): A from the view's exact Jacobian (central
/// differences without one), B = [0; M^-1 dF/du] from the generated Jacobians.
/// Throws std::invalid_argument for wrong sizes.
LinearSystem linearize_view(const ModelView& view, const std::vector<double>& x0,
                            const std::vector<double>& u0, double t0 = 0.0);

/// A view that integrates the linear system; its names are those of `nonlinear`, its
/// outputs the nonlinear outputs evaluated on the linear state (exact for outputs
/// that are linear in the state, such as DOFs in other units).
ModelView linear_view(const ModelView& nonlinear, const LinearSystem& system);

/// The output part of a linear model, y = y0 + C (x - x0) + D (u - u0): the
/// generated code has no output Jacobians, so C and D are central differences
/// of the outputs routine (Python's linear(), `lin --format openfast-lin`).
struct OutputMatrices {
    std::vector<double> C; ///< ny x 2nq, row-major
    std::vector<double> D; ///< ny x nu, row-major
};

/// At x0 = [q0, q0'], u0, t0. Throws std::invalid_argument without an outputs routine.
OutputMatrices output_matrices(const runtime::ModelView& view, const std::vector<double>& x0,
                               const std::vector<double>& u0, double t0);

} // namespace yamsc::runtime
