#pragma once
// A HydroDyn input file's strip-theory members as the runtime's strip-theory
// block (yamsc/hydro/strip_theory.hpp): joints to member ends, cross-section
// properties to diameters, the simple, depth-based or member-based coefficient
// tables to each end's coefficients, the joints' axial coefficients to their end
// effects (docs/hydrodynamics.md, "Strip theory", lists each convention).
#include "diag/diagnostics.hpp"
#include "hydrodyn/hydrodyn_input.hpp"
#include "yamsc/hydro/strip_theory.hpp"

#include <optional>

namespace yamsc::analysis {

/// The members, the water and the kinematics' position (WaveDisp); the caller fills
/// the waves, the body's origin at rest and its mesh ports. Errors (an unknown joint,
/// property set, coefficient row or axial-coefficient ID, a member of no length or
/// of a non-positive diameter) are located at the member's or joint's line: nullopt
/// after one. Warnings at their line for what is read but not modelled here.
std::optional<runtime::hydro::StripSetup> strip_setup(const hydrodyn::Input& input,
                                                      const runtime::hydro::Water& water,
                                                      diag::Diagnostics& diags);

} // namespace yamsc::analysis
