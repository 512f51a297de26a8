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

#include "yamsc/aero/bem.hpp"
#include "yamsc/aero/rotor_input.hpp"

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
};

struct NodeResult {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    // AeroDyn's element frame (orientationAnnulus for BEM_Mod 1): x along the
    // coned rotor axis (downwind), y opposite to the motion, z along the blade.
    Eigen::Vector3d x = Eigen::Vector3d::Zero(), y = Eigen::Vector3d::Zero(),
                    z = Eigen::Vector3d::Zero();
    double r_local = 0; // distance from the rotor axis [m]
    double vx = 0, vy = 0;
    ElementInput input;
    ElementSolution bem;
};

struct RotorResult {
    std::vector<std::vector<NodeResult>> blades; // [blade][node], AeroDyn's node order
    double fxh = 0, mxh = 0, power = 0;          // RtFldFxh [N], RtFldMxh [N m], RtFldPwr [W]
    double cp = 0, ct = 0, cq = 0, tsr = 0;      // RtFldCp, RtFldCt, RtFldCq, RtTSR
    double skew = 0;                             // RtSkew [rad]
    double v_avg_xh = 0;                         // RtVAvgxh [m/s]
    double r_max = 0;                            // largest local radius [m]
};

class RigidRotor {
public:
    RigidRotor(const RotorInput& input, const RotorGeometry& geometry);

    // Evaluates the rotor; warm_start tries each node's previous phi first, as
    // AeroDyn's constraint state (the default solve starts from phi = 0, as
    // AeroDyn's first step). The result's storage is reused.
    const RotorResult& evaluate(const OperatingPoint& op, bool warm_start = false);
    const RotorResult& result() const { return result_; }

private:
    const RotorInput& input_;
    RotorGeometry geometry_;
    BemOptions options_;
    std::vector<std::vector<double>> z_local_; // AeroDyn's zLocal per blade and node
    RotorResult result_;
    bool solved_ = false;
};

} // namespace yamsc::aero
