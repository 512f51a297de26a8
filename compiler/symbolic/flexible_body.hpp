#pragma once
// Kane's generalized forces of a flexible body (paper eq. 11-20, Appendix A):
// the inertial terms with the mass-matrix blocks Mxx ... Mee and the quadratic
// velocity terms k_ω, gravity (A17-A19) and the elastic forces k_e (A16).
#include "symbolic/kinematics.hpp"

namespace yamsc::symbolic {

/// Adds the body's terms to the upper triangle (r <= s) of M and to the terms of F.
/// `g` is gravity in the body's axes.
void add_flexible_body(const model::Body& body, const FrameState& f, const Vec3& g,
                       const Symbols& symbols, Matrix& M, std::vector<GiNaC::exvector>& F);

} // namespace yamsc::symbolic
