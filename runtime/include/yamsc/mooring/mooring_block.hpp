#pragma once
// Quasi-static mooring lines as a load block on one body (a floating
// platform), through that body's mesh channels (compiler/model/mesh_channels.hpp):
// it reads the body frame's position and axes and sets the lines' force and
// moment at the body's origin, in body axes, with their exact derivatives, so
// that `lin` and `trim` see the mooring's stiffness. Its outputs are each
// line's fairlead and anchor tensions.
#include <yamsc/load_block.hpp>
#include <yamsc/mooring/mooring_system.hpp>

#include <memory>
#include <string>
#include <vector>

namespace yamsc::runtime::mooring {

struct MooringSetup {
    std::vector<Line> lines;
    std::string output_prefix; // its outputs are <prefix>T_fair<n>, <prefix>T_anch<n>
    /// The body role's mesh channels in the view the block is closed around:
    /// its 18 frame outputs (position, velocity, angular velocity, x, y, z axes)
    /// and its first 6 inputs (force and moment at the origin, body axes).
    std::vector<int> frame_outputs, loads;
};

std::shared_ptr<const LoadBlock> mooring_block(MooringSetup setup);

} // namespace yamsc::runtime::mooring
