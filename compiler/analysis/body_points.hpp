#pragma once
// The points of a model's body as the runtime's meshes take them
// (yamsc/body_mesh.hpp): a SID node of a flexible body with its shapes, the
// same terms the derivation moves a joint on that node with.
#include "model/model.hpp"

#include <yamsc/body_mesh.hpp>

#include <vector>

namespace yamsc::analysis {

/// Every SID node of `body`, in SID order, as a point of its mesh (none for a
/// rigid body or one with symbolic modes).
std::vector<runtime::BodyPoint> body_points(const model::Body& body);

/// The points' undeformed distance along the body's z axis (a beam's span).
std::vector<double> spans(const std::vector<runtime::BodyPoint>& points);

} // namespace yamsc::analysis
