#pragma once
// The outputs a run's scene is drawn from (`sim --vtk`, docs/visualization.md):
// for every body its frame (origin and axes in ground components), its declared
// points, and for a rigid body its mass, centre of mass and inertia, all as
// outputs of the generated model, so the scene moves exactly as the equations
// do. A flexible body's nodes follow from its frame and its modes' coordinates
// (yamsc/body_mesh.hpp), as a load block's mesh does (mesh_channels.hpp).
// They are asked for by a command (analysis::ModelChannels::scene), never by a
// model: the model's own outputs, and the code compiled for every other
// command, stay as they are.
#include "model/model.hpp"

#include <string>

namespace yamsc::model {

/// The name of scene output `what` of body `body` ("scene.BODY.what"): what is
/// rx ry rz (origin), exx exy exz eyx ... ezz (axis a's ground component c), and
/// for a rigid body mass, comx comy comz, Ixx Iyy Izz Ixy Iyz Ixz (body axes).
std::string scene_output(const std::string& body, const std::string& what);

/// The name of the ground component `c` (x, y or z) of declared point `point`.
std::string scene_point_output(const std::string& point, char c);

/// Whether `p` is a point the model declares (not one added for a mesh).
bool is_declared_point(const Point& p);

/// Appends the scene's outputs of every body to `m` (and the points that give
/// the axes), after the model's outputs.
void add_scene_channels(Model& m);

} // namespace yamsc::model
