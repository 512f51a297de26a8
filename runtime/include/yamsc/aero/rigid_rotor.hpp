#pragma once
// A rigid rotor turning at a fixed speed in a uniform wind, evaluated with
// AeroDyn's steady BEM (BEM_Mod 1): the blade nodes placed as ElastoDyn places
// them (tower top, Twr2Shft, overhang, shaft tilt, azimuth, precone, pitch, the
// AeroDyn blade file's BlCrvAC/BlSwpAC), each node's AeroDyn frame and relative
// wind, the element solves, and AeroDyn's rotor integrals (RtFld*). This is
// also how NREL's tools make Cp/Ct/Cq tables with AeroDyn.
//
// Global frame: OpenFAST's (X downwind at zero yaw, Y to the left looking
// downwind, Z up), origin at the tower base.
#include <Eigen/Core>
#include <vector>

#include "yamsc/aero/bem_rotor.hpp"
#include "yamsc/aero/rotor_input.hpp"
#include "yamsc/wind/wind_field.hpp"

namespace yamsc::aero {

// ElastoDyn's rotor geometry (angles in rad, lengths in m); NREL 5-MW defaults.
struct RotorGeometry {
    double hub_radius = 1.5;                                 // HubRad
    double precone = -2.5 * 3.14159265358979323846 / 180;    // PreCone, every blade
    double shaft_tilt = -5.0 * 3.14159265358979323846 / 180; // ShftTilt
    double overhang = -5.0191;                               // OverHang
    double twr2shft = 1.96256;                               // Twr2Shft
    double tower_height = 87.6;                              // TowerHt
    double yaw = 0;                                          // NacYaw
};

struct OperatingPoint {
    double azimuth = 0;     // blade 1's azimuth, 0 with blade 1 up (ElastoDyn's Azimuth) [rad]
    double rotor_speed = 0; // [rad/s], positive as ElastoDyn's RotSpeed
    double pitch = 0;       // collective [rad]
    double wind_speed = 0;  // [m/s]
    // InflowWind's PropagationDir: the wind blows along (cos d, -sin d, 0) [rad].
    double wind_direction = 0;
    // If set, the wind at each node is this field's at time 0 with its reference
    // speed wind_speed (wind_field.hpp), and wind_direction is not used.
    const runtime::WindField* wind_field = nullptr;
};

class RigidRotor {
public:
    RigidRotor(const RotorInput& input, const RotorGeometry& geometry);

    // Evaluates the rotor; warm_start tries each node's previous phi first, as
    // AeroDyn's constraint state (the default solve starts from phi = 0, as
    // AeroDyn's first step). The result's storage is reused.
    const RotorResult& evaluate(const OperatingPoint& op, bool warm_start = false);
    const RotorResult& result() const { return rotor_.result(); }

private:
    const RotorInput& input_;
    RotorGeometry geometry_;
    BemRotor rotor_;     // the BEM on the motion below
    RotorMotion motion_; // the rigid rotor's, placed from the geometry
};

} // namespace yamsc::aero
