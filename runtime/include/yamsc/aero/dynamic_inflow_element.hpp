#pragma once
// A blade element with dynamic inflow, in AeroDyn's order (BEMT_CalcOutput_Inductions,
// SetInputs_for_UA): the steady BEM gives the quasi-steady inductions (DBEMT's input,
// before any correction), DBEMT filters their induced velocities, and only the
// filtered inductions get the skewed-wake redistribution and the low tip-speed-ratio
// blend, from which phi, alpha, Vrel and the loads follow.
#include "yamsc/aero/bem.hpp"
#include "yamsc/aero/dynamic_inflow.hpp"

namespace yamsc::aero {

// AeroDyn's FixedInductions: a tip or hub node whose loss is on (a zero loss
// constant) keeps a = 1, a' = 0, with neither dynamic inflow nor skew correction
// (calculate_Inductions_from_DBEMT_AllNodes, ApplySkewedWakeCorrection_AllNodes).
bool fixed_induction(const ElementInput& in, const BemOptions& opt);

// The quasi-steady a, a' of a solved element: the residual's inductions at its root,
// limited, zero without a valid root (calculate_Inductions_from_BEMT).
InductionFactors quasi_steady_induction(const ElementInput& in, const BemOptions& opt,
                                        const ElementSolution& solved);

// The inductions element e of `solved` flies with: DBEMT's filtered induced velocity
// as induction factors, but the quasi-steady ones at a fixed-induction node.
InductionFactors filtered_induction(const Dbemt& dbemt, const DbemtInput& u, const DbemtState& x,
                                    std::size_t e, const ElementInput& in, const BemOptions& opt,
                                    const ElementSolution& solved);

// Where the coefficients of an element with given inductions come from: the
// steady polar, or the caller (unsteady aerodynamics sets its own right after, so
// the polar's would be looked up for nothing).
enum class ElementCoefficients { polar, set_by_caller };

// The element with the inductions f (DBEMT's, or any) instead of the quasi-steady
// ones: the skew redistribution (except at a fixed-induction tip or hub node), the
// blend in.weight, then phi, alpha, Vrel, and with `coefficients` polar the
// coefficients and the loads per length for air density rho. phi_bem, valid and F
// are those of `solved`. Allocates nothing.
ElementSolution
element_with_induction(const ElementInput& in, const BemOptions& opt, double rho,
                       InductionFactors f, const ElementSolution& solved,
                       ElementCoefficients coefficients = ElementCoefficients::polar);

} // namespace yamsc::aero
