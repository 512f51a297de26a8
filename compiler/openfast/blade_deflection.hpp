#pragma once
// ElastoDyn's initial blade deflections (its InitBlDefl): the deck's OoPDefl and IPDefl
// are tip deflections in the coned (unpitched) blade frame; ElastoDyn solves them for
// the first flap (or, without it, the second flap) and the edge DOF with the tip values
// of its twisted shape functions, which on a twisted blade are not (1, 0) and (0, 1).
#include "openfast/deck.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::openfast {

/// The tip displacement (x: out of plane, y: in plane, blade axes before pitch) per
/// unit DOF of flap1, edge1 and flap2, as ElastoDyn's TwistedSF at its TipNode.
struct BladeTipShapes {
    std::array<double, 2> flap1{}, edge1{}, flap2{};
    /// d2(u_z)/dq_j dq_k of the tip along the blade (j, k: flap1, edge1, flap2): minus
    /// ElastoDyn's AxRedBld at the TipNode.
    std::array<std::array<double, 3>, 3> axial{};
    /// Second-order part of the blade's inertia about the shaft axis, per q_j q_k
    /// (flap1, edge1, flap2), for the cone `PreCone` and the root at `HubRad`:
    /// sum over ElastoDyn's elements of m [Phi_y Phi_y + sin^2 b Phi_x Phi_x
    /// - cos^2 b (HubRad + r) AxRedBld]. The SID's inertia is first order in q.
    std::array<std::array<double, 3>, 3> spin_inertia{};
    /// Coriolis coefficients of the blade's radial shortening, per DOF i and q_j q_k:
    /// sum over the elements of m cos b Phi_y,i AxRedBld_jk (Phi_y in plane, coned axes).
    /// The shortening's rate is radial; the spin turns it into an in-plane Coriolis
    /// force on every DOF with an in-plane shape (the edge mode), and the Coriolis force
    /// of the in-plane velocities into a radial force on the shortening (the flaps).
    /// ElastoDyn's kinematics (AxRedBld in PLinVelES) hold both; the SID does not.
    std::array<std::array<std::array<double, 3>, 3>, 3> shortening_coriolis{};
};

/// The tip shapes (and the second-order spin inertia) of every blade of the deck, from its blade
/// files discretized as ElastoDyn does (BldNodes elements). nullopt after reporting errors.
std::optional<std::vector<BladeTipShapes>> blade_tip_shapes(const openfast::OpenFastDeck& deck,
                                                            diag::Diagnostics& diags);

struct BladeInitial {
    double flap1 = 0, edge1 = 0, flap2 = 0;
    std::string warning; ///< ElastoDyn's warning when the deflection cannot be met exactly
};

/// ElastoDyn's InitBlDefl for one blade at pitch `pitch` [rad].
BladeInitial initial_blade_deflection(const BladeTipShapes& tip, double pitch, double oop,
                                      double ip, bool flap1_on, bool flap2_on, bool edge_on);

} // namespace yamsc::openfast
