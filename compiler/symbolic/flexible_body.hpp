#pragma once
// Kane's generalized forces of a flexible body (paper eq. 11-20, Appendix A):
// the inertial terms with the mass-matrix blocks Mxx ... Mee and the quadratic
// velocity terms k_ω, gravity (A17-A19) and the elastic forces k_e (A16).
#include "symbolic/kinematics.hpp"

#include <utility>
#include <vector>

namespace yamsc::symbolic {

/// Where the body's part of M a goes: the terms of (M a)_r for accelerations a.
struct MaTerms {
    const std::vector<GiNaC::symbol>& a;
    std::vector<GiNaC::exvector>& terms;
};

/// Adds the body's terms to the upper triangle (r <= s) of M, to the terms of F and
/// to those of M a. `g` is gravity in the body's axes.
void add_flexible_body(const model::Body& body, const FrameState& f, const Vec3& g,
                       const Symbols& symbols, Matrix& M, std::vector<GiNaC::exvector>& F,
                       MaTerms Ma);

/// The body's gravity and inertia loads (the negative of its momentum rate) as a
/// force and a moment about its origin, body axes, with the accelerations `qdd`
/// (one per DOF): what its Kane's terms project, before the projection.
std::pair<Vec3, Vec3> flexible_body_wrench(const model::Body& body, const FrameState& f,
                                           const Vec3& g, const Symbols& symbols,
                                           const std::vector<GiNaC::ex>& qdd);

} // namespace yamsc::symbolic
