#include "yamsc/aero/dynamic_inflow_element.hpp"

#include <algorithm>
#include <cmath>

#include "yamsc/aero/polar.hpp"

namespace yamsc::aero {

namespace {

constexpr double pi = 3.14159265358979323846;

} // namespace

bool fixed_induction(const ElementInput& in, const BemOptions& opt) {
    // A zero loss constant makes Prandtl's factor zero; at any other node it is well
    // above this bound (0.1 or more at the NREL 5-MW's node next to the tip).
    // Each factor is 2/pi acos(exp(-c)) at sin phi = 1, above 0.028 for c >= 1e-3:
    // then the product is above the bound without its exponentials.
    const double c_tip = in.blades * (in.z_tip - in.z) / (2.0 * in.z);
    const double c_hub = in.blades * (in.z - in.z_hub) / (2.0 * in.z_hub);
    if ((!opt.tip_loss || c_tip >= 1e-3) && (!opt.hub_loss || c_hub >= 1e-3)) return false;
    return prandtl_loss(in, opt, pi / 2) < 1e-6;
}

InductionFactors quasi_steady_induction(const ElementInput& in, const BemOptions& opt,
                                        const ElementSolution& solved) {
    if (!solved.valid) return {};
    const Residual r = bem_residual(in, opt, solved.phi_bem);
    if (!r.valid) return {};
    return {std::clamp(r.a, -1.0, 1.5), std::clamp(r.ap, -1.0, 1.0)};
}

InductionFactors filtered_induction(const Dbemt& dbemt, const DbemtInput& u, const DbemtState& x,
                                    std::size_t e, const ElementInput& in, const BemOptions& opt,
                                    const ElementSolution& solved) {
    if (fixed_induction(in, opt)) return quasi_steady_induction(in, opt, solved);
    return induction_factors(dbemt.output(u, x, e), in.vx, in.vy);
}

ElementSolution element_with_induction(const ElementInput& in, const BemOptions& opt, double rho,
                                       InductionFactors f, const ElementSolution& solved,
                                       ElementCoefficients coefficients_from) {
    ElementSolution s;
    s.phi_bem = solved.phi_bem;
    s.valid = solved.valid;
    s.F = solved.F;
    double a = f.axial, ap = f.tangential;
    if (opt.skew_redistribution && !fixed_induction(in, opt)) {
        // ApplySkewedWakeCorrection (Pitt/Peters) on the filtered induction.
        double chi = std::remainder((0.6 * a + 1.0) * in.chi0, 2.0 * pi);
        const double t = std::abs(chi) > pi / 2 ? (chi >= 0 ? 1.0 : -1.0) : std::tan(chi / 2.0);
        a *= 1.0 + opt.skew_factor * t * in.tip_ratio * std::sin(in.psi);
    }
    a *= in.weight;
    ap *= in.weight;
    s.a = a;
    s.ap = ap;
    const double wx = in.vx * (1.0 - a), wy = in.vy * (1.0 + ap);
    s.phi = std::atan2(wx, wy);
    s.alpha = s.phi - in.theta;
    s.vrel = std::sqrt(wx * wx + wy * wy);
    if (coefficients_from == ElementCoefficients::polar)
        set_coefficients(s, coefficients(in, s.alpha), in.chord, rho, opt);
    return s;
}

} // namespace yamsc::aero
