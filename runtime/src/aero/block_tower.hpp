#pragma once
// The tower inside `load blade_elements` (its `tower` role): AeroDyn's tower
// nodes (TwrElev) as points of the tower body, their motion each step, the
// tower's influence on the blades' wind (TwrPotent, TwrShadow) and its drag
// (TwrAero) set on the tower through its mesh inputs. The formulas are
// tower_influence.hpp's; this joins them to the model's meshes.
#include "yamsc/aero/bem_rotor.hpp"
#include "yamsc/aero/blade_element_block.hpp"
#include "yamsc/aero/tower_influence.hpp"
#include "yamsc/wind/wind_field.hpp"

#include <optional>
#include <vector>

namespace yamsc::aero {

/// The undisturbed wind at a point at one time: the field's, its reference speed
/// replaced by the V_wind the block reads (wind_field.hpp), or without a field
/// V_wind along ground x everywhere.
struct FreeWind {
    const runtime::WindField* field = nullptr;
    double time = 0, speed = 0;
    Eigen::Vector3d at(const Eigen::Vector3d& p) const {
        return field ? field->velocity(time, p, speed) : Eigen::Vector3d(speed, 0, 0);
    }
    /// at() of n points, into `out`.
    void at(const Eigen::Vector3d* p, std::size_t n, Eigen::Vector3d* out) const {
        if (field)
            field->velocities(time, p, n, speed, out);
        else
            for (std::size_t i = 0; i < n; ++i) out[i] = Eigen::Vector3d(speed, 0, 0);
    }
};

class BlockTower {
public:
    /// `channels.outputs` empty: no tower role; the influence then uses the
    /// undeflected tower standing at the ground's origin (AeroDyn's tower when
    /// nothing moves it) and the drag, with nothing to act on, is left out.
    BlockTower(const RotorInput& rotor, const TowerChannels& channels);

    /// Whether the block needs a tower at all (an influence or the drag).
    bool used() const { return influence_.active() || drag_on_; }
    /// The mesh inputs the drag is set on (empty without a tower role or TwrAero).
    const std::vector<int>& loads() const { return drag_on_ ? channels_.loads : no_loads_; }

    /// Reads the tower's frame and modes (`values`: its mesh outputs) and
    /// places AeroDyn's tower nodes in the undisturbed `wind` at each.
    void read(const double* values, const FreeWind& wind);
    /// Adds the tower's disturbance to each blade's per-node wind in `motion`
    /// (the undisturbed wind there on entry); throws std::invalid_argument on
    /// a tower strike.
    void disturb(RotorMotion& motion);
    /// The drag's loads on the tower's mesh inputs, in `loads()`'s order.
    void write_loads(double* loads);

private:
    const RotorInput& rotor_;
    TowerChannels channels_;
    TowerInfluenceModel influence_;
    bool drag_on_ = false;
    std::vector<int> no_loads_;
    std::size_t modes_ = 0;
    // The tower nodes as points of the body, placed at the first read (their
    // height above the body's origin: TwrElev less the origin's elevation).
    std::vector<runtime::BodyPoint> points_;
    TowerState state_;
    std::vector<Vec3> reference_, drag_, lumped_force_, lumped_moment_;
    std::vector<Vec3> blade_points_, blade_winds_;
    runtime::BodyFrame frame_;
    runtime::BodyLoad load_;
};

} // namespace yamsc::aero
