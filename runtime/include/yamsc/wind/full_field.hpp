#pragma once
// InflowWind's full-field wind (its Grid3D field: WindType 3, a TurbSim `.bts`,
// and WindType 5, a HAWC box), as IfW_FlowField_GetVelAcc, Grid3DField_GetCell
// and Grid3DField_GetVelLinear compute it (OpenFAST v5):
// - frozen turbulence: the grid's times pass the point (x', y', z') (wind axes,
//   turned about [0, 0, RefHt] as uniform_field.hpp says) at grid time
//   t + (InitXPosition - x') / MeanWS; a non-periodic TurbSim grid has
//   InitXPosition = half its width (its first time reaches x' = 0 at
//   t = -InitXPosition / MeanWS), a periodic one 0, a HAWC box XOffset;
// - linear in y', z' and that time between the grid's points; a periodic grid
//   wraps in time; a non-periodic one ends with its last time (InflowWind holds it
//   for half a step, then blends the last two times; later is an error);
// - below the grid: TurbSim's tower points (at y' = 0, from the grid's bottom
//   down by dz, then linearly to zero at the ground; the point's y' is not used),
//   or, for a HAWC box, linearly from the grid's bottom row to zero at the
//   ground; no tower points and not HAWC: an error, as InflowWind's;
// - beside or above the grid, or before its first time: an error (InflowWind
//   extrapolates only for OLAF's wake and lidars, which yamsc does not model);
// - at or below the ground (z' <= 0): zero;
// - a HAWC box adds its mean profile to u' after the interpolation.
//
// The reference speed (the model's V_wind): the field's horizontal speed at
// [0, 0, RefHt] at the grid's times, linearly interpolated between them (the
// hub-height wind InflowWind gives ServoDyn as HorWindV, at InflowWind's
// reference point rather than the moving hub). A replaced reference speed V
// adds (V - reference_speed(t)) s(z') to u', s the mean profile's shape (the
// mean of u' over the grid's times and y' per row, over its value at RefHt):
// the mean profile moves with V_wind, the fluctuations stay.
#include "yamsc/wind.hpp"
#include "yamsc/wind/wind_field.hpp"

#include <string>
#include <vector>

namespace yamsc::runtime {

/// The mean wind profile a HAWC box adds (InflowWind's WindProfile).
enum class MeanProfile { none = -1, constant = 0, logarithmic = 1, power_law = 2 };

struct FullFieldSetup {
    std::string source; // the file (errors)
    /// The grid in the wind's axes (periodic, dt, u_hub as MeanWS, z_hub as RefHt).
    std::vector<float> grid, tower; // as wind::FullFieldGrid's
    int ny = 0, nz = 0, n_tower = 0, nt = 0;
    double dy = 0, dz = 0, dt = 0;
    double mean_speed = 0;       // MeanWS [m/s], > 0
    double reference_height = 0; // RefHt [m], > 0
    double z_bottom = 0;         // GridBase [m]
    bool periodic = false;
    double init_x = 0; // InitXPosition [m]
    /// Below the grid, linearly to zero at the ground (InflowWind's InterpTower: HAWC).
    bool to_ground = false;
    MeanProfile profile = MeanProfile::none;
    double power_law = 0, roughness = 0; // PLExp, Z0
    double propagation_dir = 0;          // [rad]
    double vertical_flow_angle = 0;      // [rad]
};

class FullField final : public WindField {
public:
    /// Throws std::invalid_argument on sizes that disagree or a grid that does
    /// not reach RefHt.
    explicit FullField(FullFieldSetup setup);
    double reference_speed(double t) const override { return hub_(t); }
    Eigen::Vector3d velocity(double t, const Eigen::Vector3d& position,
                             double reference_speed) const override;
    bool steady() const override { return false; }
    void velocities(double t, const Eigen::Vector3d* positions, std::size_t n,
                    double reference_speed, Eigen::Vector3d* out) const override;

    /// The reference speed's samples (the V_wind signal a simulation reads).
    const WindSignal& hub() const { return hub_; }
    const FullFieldSetup& setup() const { return s_; }
    /// The velocity at `position` (ground axes) as InflowWind gives it: no
    /// replaced reference speed. Throws std::runtime_error outside the grid.
    Eigen::Vector3d interpolate(double t, const Eigen::Vector3d& position) const;

private:
    /// In the wind's axes: the velocity and the mean profile's shape at p.
    Eigen::Vector3d in_wind_axes(double t, const Eigen::Vector3d& p, double& shape) const;
    double mean_profile(double z) const;
    Eigen::Vector3d at(double t, const Eigen::Vector3d& p, double delta) const;
    [[noreturn]] void outside(double t, const Eigen::Vector3d& p, const std::string& what) const;

    FullFieldSetup s_;
    double half_width_ = 0, inv_dy_ = 0, inv_dz_ = 0, inv_mean_ = 0, rate_ = 0;
    std::vector<double> shape_; // per row, the mean u' over the value at RefHt
    Eigen::Matrix3d to_wind_;
    bool rotated_ = false;
    WindSignal hub_;
};

} // namespace yamsc::runtime
