#pragma once
// Strip theory (Morison's equation) on the members of a rigid floating platform,
// as a load block on the platform body's mesh (HydroDyn's Morison module for
// strip-theory members: docs/hydrodynamics.md, "Strip theory", lists each of
// HydroDyn's conventions and whether it is followed).
//
// Members are straight tapered circular cylinders between two points of the
// platform. The block sets, at the body's origin in body axes:
// - the buoyancy of the members' submerged volume below the still-water level
//   in the displaced position, in large rotations (end caps included);
// - on each node's strip: quadratic viscous drag on the velocity of the water
//   relative to the strip (Cd, and AxCd on a taper), Froude-Krylov and
//   diffraction inertia ((Ca + Cp), AxCa and AxCp) from the waves, and the added
//   mass (Ca, AxCa) through LoadBlock::added_mass(), constant in body axes (the
//   nodes below the still-water level in the undisplaced position: AMMod 0);
// - at the joints (member ends meeting at one point): the axial drag, added mass
//   and dynamic-pressure loads of the joint's axial coefficients.
// Potential-flow members (PropPot) get the viscous drag only.
#include <yamsc/hydro/waves.hpp>
#include <yamsc/load_block.hpp>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace yamsc::runtime::hydro {

/// Morison coefficients at one member end (interpolated linearly along the member).
struct StripCoefficients {
    double cd = 0, ca = 0, cp = 0, ax_cd = 0, ax_ca = 0, ax_cp = 0;
};

/// The axial coefficients of a joint (HydroDyn's AxCd, AxCa, AxCp of the joint's
/// JointAxID row) and its drag model (AxFDMod: 0 both ways, 1 only flow into the end).
struct JointCoefficients {
    double ax_cd = 0, ax_ca = 0, ax_cp = 0;
    int drag_model = 0;
};

struct StripMember {
    Vec3 end1{}, end2{};                 // HydroDyn global coordinates, platform undisplaced
    double diameter1 = 0, diameter2 = 0; // outer, at the ends
    StripCoefficients c1{}, c2{};        // at the ends
    double division_size = 1;            // MDivSize: elements of at most this length
    bool potential_flow = false;         // PropPot: viscous drag only (the rest is WAMIT's)
    StripCoefficients joint1_axial{}, joint2_axial{}; // the end joints' axial ax_cd, ax_ca, ax_cp
    int joint1_drag_model = 0, joint2_drag_model = 0; // the end joints' AxFDMod
};

struct StripSetup {
    std::vector<StripMember> members;
    std::shared_ptr<const WaveField> waves; // null: still water with `water`
    Water water;
    /// Where the wave kinematics are taken: at the nodes' undisplaced positions
    /// (HydroDyn's WaveDisp 0) or displaced (WaveDisp 1).
    bool kinematics_displaced = false;
    Vec3 origin_at_rest{};
    std::vector<int> frame_outputs, loads; // the body role's mesh (18 and 6)
    std::string output_prefix;             // outputs <prefix>Fxi ... <prefix>Mzi, <prefix>Vsub
};

/// The block; throws std::invalid_argument for a setup it cannot use (no member,
/// a member of zero length or diameter, ports of the wrong size).
std::shared_ptr<const LoadBlock> strip_theory_block(StripSetup setup);

} // namespace yamsc::runtime::hydro
