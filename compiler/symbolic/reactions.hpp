#pragma once
// Reaction loads (docs/theory.md, docs/language.md): the force and moment a
// body's joint transmits to it from its parent, by Newton-Euler over the bodies
// it carries, with the accelerations q'' as symbols (the generated `outputs`
// solves them from M q'' = F).
#include "symbolic/body_terms.hpp"

#include <map>
#include <vector>

namespace yamsc::symbolic {

/// Inertia tensor about the COM, body axes, from (Ixx, Iyy, Izz, Ixy, Iyz, Ixz).
Mat3 inertia_tensor(const model::Body& b, const Symbols& s);

class Reactions {
public:
    /// `applied`: each body's applied forces and torques about its origin, body axes.
    Reactions(const model::Model& m, const std::vector<FrameState>& frames, const Symbols& symbols,
              std::vector<Wrench> applied);

    /// What the joint of `body` transmits to it, ground axes, about its origin;
    /// built once per body.
    const Wrench& of(int body);

    /// What the part of flexible `body` inboard of its SID node `node` transmits to
    /// the part beyond it (with every body attached there), ground axes, about the
    /// deformed node `cut` (its frame: the node step's); built once per section.
    /// Needs the body's section integrals (model::Flexible::sections).
    const Wrench& section(int body, int node, const FrameState& cut);

private:
    /// Gravity, inertia and applied loads of one body about its origin, its axes.
    Wrench load(std::size_t b) const;
    bool carried_by(int i, int root) const;

    const model::Model& m_;
    const std::vector<FrameState>& frames_;
    const Symbols& symbols_;
    std::vector<GiNaC::ex> qdd_;
    std::vector<Wrench> applied_; // per body: its applied forces and torques
    std::vector<Wrench> loads_;   // per body: applied_ + load(b)
    std::map<int, Wrench> done_;
    std::map<std::pair<int, int>, Wrench> sections_;
};

} // namespace yamsc::symbolic
