#pragma once
// What AeroDyn's primary file, blade files and airfoil files say about one rotor,
// as plain data with types for every switch. The AeroDyn reader
// (formats/aerodyn, converted in compiler/analysis) fills it; the blade-element
// code reads it. Lengths in m, angles in rad, as AeroDyn stores them after
// reading (the files give degrees).
#include <vector>

#include "yamsc/aero/airfoil.hpp"

namespace yamsc::aero {

// Wake_Mod (OpenFAST v4/v5); the older WakeMod 2 (DBEMT) reads as bem with a
// dynamic inflow model other than none.
enum class WakeModel { none = 0, bem = 1, free_vortex = 3 };
enum class SkewModel { remove_non_normal = -1, none = 0, active = 1 }; // Skew_Mod
enum class SkewRedistribution { none = 0, pitt_peters = 1 };           // SkewRedistr_Mod
enum class DynamicInflow {
    none = 0,
    constant_tau1 = 1,
    varying_tau1 = 2,
    continuous = 3
};                         // DBEMT_Mod
enum class UnsteadyModel { // UA_Mod
    none = 0,
    gonzalez = 2,
    minnema_pierce = 3,
    hgm = 4,
    hgm_vortex = 5,
    oye = 6,
    boeing_vertol = 7
};
enum class TowerPotential { none = 0, baseline = 1, bak = 2 }; // TwrPotent
enum class TowerShadow { none = 0, powles = 1, eames = 2 };    // TwrShadow

// One line of an AeroDyn blade file: a blade node, along the blade's pitch axis.
struct BladeNode {
    double span = 0;        // BlSpn: from the blade root [m]
    double curve_ac = 0;    // BlCrvAC: out-of-plane offset of the aerodynamic centre (prebend) [m]
    double sweep_ac = 0;    // BlSwpAC: in-plane offset (sweep) [m]
    double curve_angle = 0; // BlCrvAng [rad]
    double twist = 0;       // BlTwist [rad]
    double chord = 0;       // BlChord [m]
    int airfoil = 0;        // BlAFID - 1: index into RotorInput::airfoils
};

struct TowerNode {
    double elevation = 0; // TwrElev [m]
    double diameter = 0;  // TwrDiam [m]
    double cd = 0;        // TwrCd
    double ti = 0;        // TwrTI (TwrShadow 2)
};

struct RotorInput {
    WakeModel wake = WakeModel::bem;
    int bem_mod = 1; // BEM_Mod: 1 legacy (no sweep, pitch, twist in the frame), 2 polar
    SkewModel skew = SkewModel::active;
    bool skew_momentum_correction = false;
    SkewRedistribution skew_redistribution = SkewRedistribution::pitt_peters;
    double skew_redistribution_factor = 15.0 * 3.14159265358979323846 / 32.0;
    bool tip_loss = true, hub_loss = true, tangential_induction = true;
    bool axial_drag = false, tangential_drag = false; // AIDrag, TIDrag
    double induction_tolerance = 0;                   // IndToler; 0: AeroDyn's default
    double inflow_angle_tolerance = 0; // Brent's bracket [rad]; 0: AeroDyn's (BemOptions)
    int max_iterations = 100;
    DynamicInflow dynamic_inflow = DynamicInflow::none;
    double tau1_const = 4; // [s]
    UnsteadyModel unsteady = UnsteadyModel::none;
    bool f_lookup = true;                          // FLookup
    bool aoa_34 = true;                            // AoA34
    double ua_start_radius = 0, ua_end_radius = 1; // fractions of the rotor radius
    TowerPotential tower_potential = TowerPotential::none;
    TowerShadow tower_shadow = TowerShadow::none;
    bool tower_drag = false;         // TwrAero
    bool use_pitching_moment = true; // UseBlCm
    double air_density = 1.225, kinematic_viscosity = 1.464e-5, speed_of_sound = 335;
    std::vector<Airfoil> airfoils;              // AFNames, in order
    std::vector<std::vector<BladeNode>> blades; // ADBlFile(k), one per blade
    std::vector<TowerNode> tower;
    std::vector<int>
        output_nodes; // BlOutNd: the blade nodes (1-based) with outputs, NBlOuts of them
};

} // namespace yamsc::aero
