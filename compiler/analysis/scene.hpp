#pragma once
// A run's scene (docs/visualization.md): every body's geometry at each output
// row, in ground axes, from the scene's outputs of the generated model
// (model/scene_channels.hpp) and, for a flexible body, its SID nodes moved by
// the derivation's own node kinematics (yamsc/body_mesh.hpp):
// - every body: its frame, three axis segments scaled to the model's size;
// - a rigid body: a skeleton line from its origin to each declared point on it
//   and each child's joint, and the uniform box with its mass and principal
//   moments about its centre of mass, along its principal axes, where it has one;
// - a flexible body: its deflected line through its SID nodes;
// - a declared point: a marker.
// The topology is fixed when the scene is made (from the first row); each row
// only moves the points.
#include "model/model.hpp"
#include "vtk/scene.hpp"

#include <yamsc/body_mesh.hpp>
#include <yamsc/simulation.hpp>

#include <string>
#include <vector>

namespace yamsc::analysis {

/// A surface along a flexible body's z axis (its span), where the model's data
/// give its sections: a blade's chord and twist (an elliptic section, its
/// thickness a fraction of the chord, the aerodynamic centre at a quarter chord),
/// a tower's diameter (a tube). Spans between the body's first and last SID node.
struct SurfaceSection {
    double span = 0.0;  // along the body's z axis, from its origin [m]
    double chord = 0.0; // the section's width (a tube: its diameter) [m]
    double twist = 0.0; // about -z (AeroDyn's BlTwist), from the body's y axis [rad]
};
struct BodySurface {
    int body = -1;
    bool tube = false;
    bool elevations = false; // spans are heights above the ground (AeroDyn's TwrElev)
    std::vector<SurfaceSection> sections;
};

class Scene {
public:
    /// `m`: the checked model with its scene outputs (ModelChannels::scene);
    /// `run`: a run of it with at least one row (its states start with q; the
    /// first row fixes the box sizes and the axes' length). Throws
    /// diag::InternalError when a scene output is missing.
    Scene(const model::Model& m, const runtime::SimulationResult& run,
          const std::vector<BodySurface>& surfaces = {});

    const vtk::Topology& topology() const { return topology_; }

    /// The points at row `row` of `run` (x y z per point).
    std::vector<double> points(const runtime::SimulationResult& run, std::size_t row) const;

    /// The output columns of the scene (indices into the outputs), rising.
    const std::vector<int>& scene_outputs() const { return scene_outputs_; }

    /// Where a body's frame is in the outputs, and its nodes.
    struct BodySource {
        int r = -1, e = -1;     // first output of the origin (3) and of the axes (9)
        std::vector<int> modes; // the DOF of each mode (flexible)
        std::vector<runtime::BodyPoint> nodes;
    };
    /// How one point of the scene follows the motion.
    struct PointSource {
        enum class Kind { output, body_fixed, node, section } kind = Kind::output;
        int body = -1;
        int output = -1;                                 // output: the first of three
        Eigen::Vector3d local = Eigen::Vector3d::Zero(); // body_fixed: from the origin (body axes)
        std::size_t node = 0;                            // node: index into the body's nodes
    };

private:
    std::vector<BodySource> bodies_;
    std::vector<runtime::BodyPoint> sections_; // the sections' centres on their bodies
    std::vector<PointSource> sources_;
    vtk::Topology topology_;
    std::vector<int> scene_outputs_;
};

/// `run` without the outputs `columns` (indices into its outputs, rising): what
/// sim writes when the scene's outputs were compiled only for the scene.
runtime::SimulationResult without_outputs(const runtime::SimulationResult& run,
                                          const std::vector<int>& columns);

} // namespace yamsc::analysis
