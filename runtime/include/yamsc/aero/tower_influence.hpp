#pragma once
// The tower in AeroDyn: its influence on the wind the blades see (potential
// flow, TwrPotent 1 and 2; shadow, TwrShadow 1 and 2) and its own drag
// (TwrAero), as AeroDyn v15 (OpenFAST v4/v5) computes them in TwrInfl,
// getLocalTowerProps, CalculateTowerInfluence and ADTwr_CalcOutput.
//
// The tower is AeroDyn's tower table (TowerNode: TwrElev, TwrDiam, TwrCd,
// TwrTI) and, at one instant, its line in space: the deflected positions of
// those nodes, each node's axis, and the undisturbed wind and structural
// velocity there (AeroDyn's TowerMotion mesh and the wind InflowWind gives at
// its nodes). The caller owns that state and refills it each step; nothing
// here allocates. Vectors are in the inertial frame, SI units.
#include <array>
#include <cstddef>
#include <vector>

#include "yamsc/aero/rotor_input.hpp"

namespace yamsc::aero {

using Vec3 = std::array<double, 3>;

// The tower at one instant, node for node with the tower table (same size,
// base first). position: deflected node (Position + TranslationDisp);
// axis: unit vector along the tower at the node (third row of the node's
// orientation; used where a point lies beyond the tower's ends and for the
// drag); wind: undisturbed wind at the node; velocity: the node's structural
// translational velocity.
struct TowerState {
    std::vector<Vec3> position, axis, wind, velocity;
};

// The undeflected state: node j at base + TwrElev(j) along z, axis z, still
// air and no motion. AeroDyn places its tower mesh so (x and y of the
// tower's base, z the elevation itself, not added to the base's z). The one
// function here that allocates: call it once to size the state.
TowerState undeflected_tower(const std::vector<TowerNode>& table, const Vec3& base);

// Where a point lies with respect to the tower (AeroDyn's getLocalTowerProps).
// The frame (x_hat, y_hat, z_hat) is AeroDyn's theta_tower_trans: z_hat along
// the tower, x_hat along the relative wind's component normal to the tower,
// y_hat = z_hat x x_hat. Distances are normalized by the local radius.
struct TowerProjection {
    bool on_element = false;             // false: the nearest node was used (no element
                                         // the point projects orthogonally onto)
    std::size_t index = 0;               // the element (nodes index, index + 1) or the node
    double fraction = 0;                 // position along the element [0, 1]
    double diameter = 0, cd = 0, ti = 0; // interpolated along the element
    Vec3 r{};                            // from the tower's line to the point
    Vec3 x_hat{}, y_hat{}, z_hat{};      // all zero when w is zero
    double w = 0;                        // relative wind normal to the tower
    double xbar = 1, ybar = 0, zbar = 0;
    double clearance = 0;  // |r| - diameter / 2 (AeroDyn's TwrClrnc)
    bool disturbs = false; // 0.01 D < clearance <= 20 D (DisturbInflow)
};

// Options of the tower's influence on the blades' wind.
struct TowerInfluenceModel {
    TowerPotential potential = TowerPotential::none;
    TowerShadow shadow = TowerShadow::none;
    bool active() const { return potential != TowerPotential::none || shadow != TowerShadow::none; }
};

// The nearest element onto which the point projects orthogonally (ends
// snapped within single-precision rounding, as AeroDyn does), else the
// nearest node; at the first or last node the point's height beyond it
// tapers the influence over one radius (zbar, cos(pi/2 zbar)). The table and
// the state must have the same size, at least two nodes, no two coincident.
TowerProjection project_onto_tower(const std::vector<TowerNode>& table, const TowerState& state,
                                   const Vec3& point);

// AeroDyn's CalculateTowerInfluence with W_tower = 1: the disturbance in the
// tower frame, {axial along x_hat, transverse along y_hat}, as fractions of
// the normal relative wind. Potential flow only where |zbar| < 1; shadow only
// downwind (xbar > 0) and where |zbar| < 1; the shadow's deficit is limited
// to -0.5.
struct TowerDisturbance {
    double axial = 0, transverse = 0;
};
TowerDisturbance tower_disturbance(const TowerInfluenceModel& model, double xbar, double ybar,
                                   double zbar, double cd, double ti);

// The wind at a point (a blade node's deflected position) disturbed by the
// tower: the undisturbed wind there plus the disturbance times w, in the
// tower frame. The projection is returned for the clearance (AeroDyn stops
// with "Tower strike" when a blade node's clearance is <= 0; that is the
// caller's decision).
struct DisturbedWind {
    Vec3 wind{};
    TowerProjection projection;
};
DisturbedWind disturbed_wind(const TowerInfluenceModel& model, const std::vector<TowerNode>& table,
                             const TowerState& state, const Vec3& point, const Vec3& undisturbed);

// Every blade node of a rotor at once (AeroDyn's TwrInfl): wind[i] is the
// undisturbed wind at points[i] on input, the disturbed wind on output.
// Returns the smallest clearance of those points (a tower strike if <= 0).
double disturb_winds(const TowerInfluenceModel& model, const std::vector<TowerNode>& table,
                     const TowerState& state, const Vec3* points, Vec3* wind, std::size_t count);

// Drag per unit length of the tower at a node (ADTwr_CalcOutput): with V the
// wind minus the structural velocity and V_n its part normal to the axis,
// f = 1/2 rho Cd D |V_n| V_n [N/m]; no moment.
Vec3 tower_drag_per_length(const TowerNode& node, double air_density, const Vec3& wind,
                           const Vec3& velocity, const Vec3& axis);

// Its derivative with respect to the node's velocity (the tower's aerodynamic
// damping), row-major d f_i / d velocity_j [N s/m^2]:
// -1/2 rho Cd D (|V_n| P + V_n V_n^T / |V_n|), P = I - axis axis^T; zero where
// V_n vanishes. With respect to the wind it is the opposite.
std::array<double, 9> tower_drag_velocity_jacobian(const TowerNode& node, double air_density,
                                                   const Vec3& wind, const Vec3& velocity,
                                                   const Vec3& axis);

// The drag at every node of the state, into force[0 .. table.size()).
void tower_drag(const std::vector<TowerNode>& table, const TowerState& state, double air_density,
                Vec3* force);

// Loads per length at the nodes of a line mesh (AeroDyn's TowerLoad: linear
// along each element) as point loads at the same nodes, as OpenFAST's mesh
// mapping lumps them (Lump_Line2_to_Point) before passing them to the
// structure: per element of reference length L (from reference, undeflected)
// and deflected span dp (from position), F1 += L/6 (2 f1 + f2),
// F2 += L/6 (f1 + 2 f2), and the couple L/12 dp x (f1 + f2) at the first node,
// its opposite at the second. Total force and moment about any point are
// those of the distributed load. force and moment are overwritten.
void lump_line_loads(const Vec3* reference, const Vec3* position, const Vec3* per_length,
                     std::size_t count, Vec3* force, Vec3* moment);

} // namespace yamsc::aero
