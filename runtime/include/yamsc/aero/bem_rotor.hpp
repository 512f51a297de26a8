#pragma once
// AeroDyn's BEM (BEM_Mod 1) on a rotor in any motion: the hub's frame and each
// blade node's position, velocity and orientation, as the structure gives them
// (the flexible blades' meshes, or the rigid rotor's kinematics). It forms
// AeroDyn's frames from the orientations (Calculate_MeshOrientation_
// NoSweepPitchTwist: the annulus frame without sweep, pitch and twist; the
// twist, pitch and elastic twist extracted as the node's angle about the
// blade), the disk-averaged relative wind, the skew angle and azimuths
// (DiskAvgValues), solves each element (bem.hpp) and integrates the rotor's
// loads about the hub (RtFld*).
#include <Eigen/Core>
#include <vector>

#include "yamsc/aero/rigid_rotor.hpp"
#include "yamsc/aero/rotor_input.hpp"

namespace yamsc::aero {

/// Ground axes throughout; orientations as rotation matrices whose columns are
/// the frame's axes (the transposes of AeroDyn's orientation matrices).
struct RotorMotion {
    Eigen::Vector3d hub_position = Eigen::Vector3d::Zero();
    Eigen::Matrix3d hub_axes = Eigen::Matrix3d::Identity(); // x: the rotor axis, downwind
    Eigen::Vector3d hub_angular_velocity = Eigen::Vector3d::Zero();
    struct Blade {
        Eigen::Matrix3d root_axes = Eigen::Matrix3d::Identity(); // pitched root: z along the blade
        std::vector<Eigen::Vector3d> position, velocity;         // per AeroDyn node
        std::vector<Eigen::Matrix3d> axes; // per node: the root axes turned by the node's
                                           // curve and twist (and its elastic rotation)
    };
    std::vector<Blade> blades;
};

class BemRotor {
public:
    /// `hub_radius`: the blades' roots from the rotor axis (Prandtl's hub loss, zLocal).
    BemRotor(const RotorInput& input, double hub_radius);

    /// The rotor in uniform wind `wind` (ground axes) at `motion`; warm_start
    /// tries each node's previous inflow angle first (AeroDyn's constraint
    /// state). The result's storage is reused.
    const RotorResult& evaluate(const RotorMotion& motion, const Eigen::Vector3d& wind,
                                bool warm_start);
    const RotorResult& result() const { return result_; }

    /// The rotor's loads and coefficients (RtFld*) again from the nodes' element
    /// solutions, after a caller replaced them (dynamic inflow, unsteady
    /// airfoil coefficients); `motion` as given to the last evaluate.
    const RotorResult& integrate(const RotorMotion& motion);
    /// The nodes' results, for such a replacement.
    std::vector<std::vector<NodeResult>>& nodes() { return result_.blades; }

    /// A node's orientation relative to its blade's root, from the blade file:
    /// curve angle about y, then the twist about -z (AeroDyn's EulerConstruct(0, crv, -twist)).
    static Eigen::Matrix3d node_axes_in_root(const BladeNode& node);

private:
    const RotorInput& input_;
    double hub_radius_;
    BemOptions options_;
    std::vector<std::vector<double>> z_local_;
    RotorResult result_;
    bool solved_ = false;
};

} // namespace yamsc::aero
