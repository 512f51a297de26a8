#pragma once
// The channels through which a load block reaches a body one of its roles names
// (RoleTarget::body): the "mesh" of that body. The block reads the motion of the
// body's frame and of its modes, and sets the loads on it; the runtime
// (yamsc/body_mesh.hpp) turns them into the motion of any point of the body
// (a blade's aerodynamic nodes, following its deflection) and turns forces and
// moments at such points into these loads exactly (Σ Jᵀ f), so that every
// distributed load takes one road into the equations.
//
// Per body role, in this order:
//   outputs  position, velocity and angular velocity of the body frame (ground
//            axes, 3 each), its x, y and z axes in ground components (3 each),
//            then each mode's coordinate and each mode's rate;
//   inputs   force and moment at the body's origin in body axes (3 each), then
//            the generalized force on each mode.
// They follow the model's declared channels, named `BLOCK.ROLE.what` (not
// identifiers: they cannot clash with the model's names), and are part of the
// equations: a block with a body role changes the generated code.
#include "model/model.hpp"

#include <string>
#include <vector>

namespace yamsc::model {

/// Outputs per body before the modes', inputs per body before the modes'.
constexpr int mesh_frame_outputs = 18;
constexpr int mesh_frame_inputs = 6;

/// Whether any role of `block` names a body.
bool has_mesh(const LoadBlock& block);

/// The mesh channels' names for role `role` of `block` (bound to a body of `m`).
std::vector<std::string> mesh_output_names(const Model& m, const LoadBlock& block, int role);
std::vector<std::string> mesh_input_names(const Model& m, const LoadBlock& block, int role);

/// Appends every block's mesh channels to `m`: the outputs and inputs above, the
/// points that give the axes, and the loads they drive (`force`/`torque on` the
/// body in its axes, `genforce` on its modes).
void add_mesh_channels(Model& m);

} // namespace yamsc::model
