#pragma once
// What one body adds to Kane's equations before they are projected on the DOFs
// (paper eq. 6-20, A1-A19): its inertia about its origin, the gravity and
// inertia loads on it without q'', and for a flexible body the coupling of its
// own modes. symbolic/projection.hpp projects them; a rigid body is a flexible
// one without modes.
#include "symbolic/kinematics.hpp"

#include <optional>
#include <vector>

namespace yamsc::symbolic {

/// Resultant force and moment about a body's origin.
struct Wrench {
    Vec3 force, moment;
};

/// Mass, first moment and inertia about a frame's origin, in its axes: the 6 x 6
/// spatial inertia [[m I, -[md]x], [[md]x, J]].
struct Inertia {
    GiNaC::ex mass = 0;
    Vec3 md; // first moment of mass (mass x centre of mass)
    Mat3 J;  // about the origin, not the centre of mass

    /// The momentum of velocity v and angular velocity w: (m v + w x md, md x v + J w).
    Wrench momentum(const Vec3& v, const Vec3& w) const;
};

/// A mode of a flexible body: its DOF, its momentum coupling with the body's
/// frame (the rows of Ct and Cr: ∫Φ dm and ∫ s x Φ dm, stiffening included) and
/// its generalized force without q'' (inertial, gravity, elastic; eq. A16-A19).
struct ModeTerms {
    int dof = -1;
    Vec3 ct, cr;
    GiNaC::ex force = 0;
};

/// A rigid body's centre of mass and inertia about it: its own share of M is
/// cheapest from these (m vG_r · vG_s + ω_r · J_G ω_s, eq. 8).
struct RigidInertia {
    Vec3 com;
    Mat3 JG;
};

struct BodyTerms {
    Inertia inertia;                        // at the current q
    std::optional<RigidInertia> rigid;      // a rigid body's, for its own share
    Wrench load;                            // gravity and inertia without q''
    std::vector<ModeTerms> modes;           // none for a rigid body
    std::vector<std::vector<GiNaC::ex>> Me; // modal mass, between its modes
};

/// A rigid body's terms (eq. 6-9): `g` is gravity in the body's axes.
BodyTerms rigid_body_terms(const model::Body& body, const FrameState& f, const Vec3& g,
                           const Symbols& symbols);

/// `inertia` (in a child frame's axes about its origin) in the axes of the frame it
/// hangs from, about that frame's origin; the child's axes are the columns of R
/// and its origin is p, both in the parent's axes.
Inertia to_parent(const Inertia& inertia, const Mat3& R, const Vec3& p);
/// The same for a wrench about the child's origin.
Wrench to_parent(const Wrench& w, const Mat3& R, const Vec3& p);

} // namespace yamsc::symbolic
