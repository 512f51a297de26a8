#pragma once
// The tower inside `load blade_elements` (its `tower` role): AeroDyn's tower
// nodes (TwrElev) as points of the tower body, their motion each step, the
// tower's influence on the blades' wind (TwrPotent, TwrShadow) and its drag
// (TwrAero) set on the tower through its mesh inputs. The formulas are
// tower_influence.hpp's; this joins them to the model's meshes.
#include "yamsc/aero/bem_rotor.hpp"
#include "yamsc/aero/blade_element_block.hpp"
#include "yamsc/aero/tower_influence.hpp"

#include <optional>
#include <vector>

namespace yamsc::aero {

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
    /// places AeroDyn's tower nodes in the undisturbed uniform `wind`.
    void read(const double* values, const Eigen::Vector3d& wind);
    /// Fills each blade's per-node wind in `motion` with the disturbed wind
    /// at its nodes; throws std::invalid_argument on a tower strike.
    void disturb(RotorMotion& motion, const Eigen::Vector3d& wind);
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
