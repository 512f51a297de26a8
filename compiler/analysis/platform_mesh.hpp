#pragma once
// What the platform kinds (`load mooring`, `load hydrodyn`: model/load_kinds.hpp,
// PlatformRole) share: the platform body's mesh channels in the view, where its
// origin is at rest, and the water the declaration binds.
#include "analysis/load_block_kinds.hpp"

#include <array>
#include <optional>
#include <vector>

namespace yamsc::analysis {

struct PlatformMesh {
    /// The body role's 18 frame outputs and 6 frame inputs (force, moment at
    /// the origin in body axes) in the view the block is closed around.
    std::vector<int> frame_outputs, loads;
    /// Where the body's origin is in ground axes with every DOF, rate and input
    /// zero: a point the input files give in their global coordinates
    /// (platform undisplaced, z up from the still-water level) is
    /// origin_at_rest + its position in body axes.
    std::array<double, 3> origin_at_rest{};
    /// The body's x, y, z axes at rest in ground components (9..17 of the frame).
    std::array<double, 9> axes_at_rest{1, 0, 0, 0, 1, 0, 0, 0, 1};

    /// A point given in those global coordinates, in body axes from the origin.
    std::array<double, 3> body_point(const std::array<double, 3>& global) const;
    /// Whether the body's axes at rest are the ground's (HydroDyn's and WAMIT's
    /// matrices are written in them).
    bool axes_are_ground() const;
};

PlatformMesh platform_mesh(const model::LoadBlock& decl, const BlockContext& c);

/// The water the declaration's parameters give (PlatformRole::depth, density,
/// gravity): nullopt for a role left unbound.
struct BoundWater {
    std::optional<double> depth, density, gravity;
};

BoundWater bound_water(const model::LoadBlock& decl, const BlockContext& c);

} // namespace yamsc::analysis
