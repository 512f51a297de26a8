#pragma once
// The linear model of a view about an operating point in second-order form
// (paper eq. 25), with the first-order A and B and the modes:
//
//   M0 δq'' + C0 δq' + K0 δq = Q0 δu,
//
// M0 = M(q0), C0 = -∂F/∂q', Q0 = ∂F/∂u, and K0 = -M0 ∂q''/∂q taken from the state
// matrix, so that K0 includes -∂(M q''0)/∂q when the point is not an equilibrium
// (q''0 != 0). What `yamsc lin` prints and writes as JSON.
#include "yamsc/modal.hpp"
#include "yamsc/model_view.hpp"

#include <vector>

namespace yamsc::runtime {

struct SecondOrderModel {
    int nq = 0, nu = 0;
    std::vector<double> M0, C0, K0;  ///< nq x nq, row-major
    std::vector<double> Q0;          ///< nq x nu
    std::vector<double> A, B;        ///< 2nq x 2nq and 2nq x nu
    std::vector<double> F0;          ///< F(q0, q0', u0): zero at an equilibrium
    double equilibrium_residual = 0; ///< max |q''0| = max |M0⁻¹ F0|
    std::vector<Mode> modes;         ///< of A, sorted by frequency
};

/// The model of `view` at (q0, q0', u0, t0). Throws std::invalid_argument for
/// wrong sizes.
SecondOrderModel second_order_model(const ModelView& view, const std::vector<double>& q0,
                                    const std::vector<double>& qd0, const std::vector<double>& u0,
                                    double t0 = 0.0);

} // namespace yamsc::runtime
