#pragma once
// Kane's projection of the bodies' terms on the DOFs (paper eq. 7-10, 18):
// M_rs = Σ_b J_rᵀ I_b J_s and F_r = Σ_b J_r · W_b over the bodies b that r and s
// move, with J the 6-vector of partial velocities in b's axes.
//
// Summed body by body, every body below the rotor adds its share to every pair
// of the DOFs above it. Through composite bodies (the composite-rigid-body
// algorithm in Kane's form) each pair is summed once: a DOF that first moves the
// tree at body b (an *anchor*: b's joint steps use it, or it is one of b's own
// modes) moves b's whole subtree rigidly with b, so the subtree's share is
// J_r(b)ᵀ C_b J_s(b) with C_b the subtree's inertia about b's origin, and
// F_r's is J_r(b) · (the subtree's loads moved to b). docs/theory.md derives it.
//
// Moving an inertia through a joint's rotation costs more than projecting a
// body with a diagonal inertia on a few DOFs, so which bodies join composites is
// a choice (Grouping); a DOF whose anchors overlap (a joint that reuses a DOF its
// parent already uses) is summed body by body.
#include "symbolic/body_terms.hpp"

#include <map>
#include <set>

namespace yamsc::symbolic {

/// Which bodies are summed through composites; the others body by body.
enum class Grouping {
    none,     // every body on its own (Kane's sums as written)
    flexible, // the flexible bodies
    all,      // every body
};

class Projection {
public:
    /// `frames`: each body's frame; `relative`: each body's frame in its parent's
    /// (its joint steps from the identity); `terms`: each body's terms. Bodies are
    /// in the model's order, parents first.
    Projection(const model::Model& m, const std::vector<FrameState>& frames,
               std::vector<FrameState> relative, std::vector<BodyTerms> terms, Grouping grouping);

    /// M_rs without the applied loads' q'' terms.
    GiNaC::ex mass(int r, int s);
    /// F_r without the applied loads.
    GiNaC::ex force(int r) const;

private:
    struct Anchor {
        int body;
        bool elastic; // the DOF is the body's own mode: it moves that body only
    };
    struct Partial {
        Vec3 v, w;
        bool moves = false;
    };

    Partial partial(int body, int r) const;
    /// Index of DOF r among body's modes, -1 if it is not one of them.
    int mode(int body, int r) const;
    bool in_subtree(int body, int root) const;
    bool anchors_overlap(const Anchor& a, const Anchor& b) const;
    /// Whether M_rs can be summed over the anchors of s: r moves each of their
    /// subtrees rigidly with the anchor body.
    bool projects_over(int s, int r) const;
    GiNaC::ex share(const Anchor& at, int s, int r);
    /// Body b's own M_rs and F_r.
    GiNaC::ex body_mass(std::size_t b, int r, int s) const;
    GiNaC::ex body_force(std::size_t b, int r) const;

    const model::Model& m_;
    const std::vector<FrameState>& frames_;
    std::vector<FrameState> relative_;
    std::vector<BodyTerms> terms_;
    std::vector<bool> grouped_;                // per body: summed through composites
    std::vector<std::set<int>> introduced_;    // per body: the DOFs its joint steps use
    std::vector<Inertia> composite_;           // per body: its grouped subtree's, about its origin
    std::vector<Wrench> loads_;                // per body: the same for the loads
    std::vector<std::vector<Anchor>> anchors_; // per DOF
    std::vector<bool> composite_ok_;           // per DOF: its anchors do not overlap
    std::map<std::pair<int, int>, Wrench> momentum_; // (s, body): C_body J_s
    std::map<int, Wrench> momentum_at_parent_;       // mode s: (ct, cr) in the parent's
};

/// Adds the terms of (M a)_r for accelerations a, body by body (the Jacobians and
/// the tangent form).
void add_mass_times(const std::vector<FrameState>& frames, const std::vector<BodyTerms>& terms,
                    const std::vector<GiNaC::symbol>& a, std::vector<GiNaC::exvector>& out);

} // namespace yamsc::symbolic
