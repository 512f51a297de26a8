#pragma once
// Rigid-body properties of the parts of an ElastoDyn turbine whose DOFs are off, computed
// the way ElastoDyn discretizes them (so that the model carries the same mass):
// BldNodes (TwrNodes) equal elements, the mass density interpolated linearly at the
// element centres, times the file's mass adjustment factor, lumped there.
#include "openfast/deck.hpp"

#include <array>
#include <optional>

namespace yamsc::openfast {

struct RigidProperties {
    double mass = 0;
    std::array<double, 3> cm{}; ///< centre of mass in the body frame [m]
    std::array<double, 6>
        inertia{}; ///< about the CM: Ixx, Iyy, Izz, Ixy, Iyz, Ixz (tensor entries)
};

/// The hub, the blades (with their precone, at equal azimuth spacing) and the tip masses,
/// in the rotor frame: origin at the apex, x along the shaft (downwind), blade 1 along z.
/// The generator is not included. nullopt after reporting errors in the blade files.
std::optional<RigidProperties> rigid_rotor(const openfast::OpenFastDeck& deck,
                                           diag::Diagnostics& diags);

/// Blade k (1-based) with its tip mass, in its own frame: origin at the root, z along the
/// blade (its points are on the axis: no inertia about it). nullopt after reporting errors.
std::optional<RigidProperties> rigid_blade(const openfast::OpenFastDeck& deck, int k,
                                           diag::Diagnostics& diags);

/// The tower as a rigid body in its base frame (z up), `length` = TowerHt - TowerBsHt.
std::optional<RigidProperties> rigid_tower(const openfast::OpenFastDeck& deck,
                                           diag::Diagnostics& diags);

} // namespace yamsc::openfast
