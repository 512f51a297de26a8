#pragma once
// Kane's generalized forces of a flexible body (paper eq. 11-20, Appendix A):
// the inertial terms with the mass-matrix blocks Mxx ... Mee and the quadratic
// velocity terms k_ω, gravity (A17-A19) and the elastic forces k_e (A16).
#include "symbolic/body_terms.hpp"

#include <utility>
#include <vector>

namespace yamsc::symbolic {

/// The body's terms at the current q in its axes (eq. 11-20, A1-A19): `g` is
/// gravity in the body's axes.
BodyTerms flexible_body_terms(const model::Body& body, const FrameState& f, const Vec3& g,
                              const Symbols& symbols);

/// The body's gravity and inertia loads (the negative of its momentum rate) as a
/// force and a moment about its origin, body axes, with the accelerations `qdd`
/// (one per DOF): what its Kane's terms project, before the projection.
std::pair<Vec3, Vec3> flexible_body_wrench(const model::Body& body, const FrameState& f,
                                           const Vec3& g, const Symbols& symbols,
                                           const std::vector<GiNaC::ex>& qdd);

} // namespace yamsc::symbolic
