#pragma once
// The rows of a model's constraints (model/constraint_kinds.hpp) from the tree's
// kinematics: each kind's rows are built by its own file
// (symbolic/constraints/<kind>.cpp), registered by kind in registry.cpp.
#include "model/model.hpp"
#include "symbolic/equations.hpp"
#include "symbolic/expressions.hpp"
#include "symbolic/kinematics.hpp"

#include <map>

namespace yamsc::symbolic {

/// Where a frame or point a constraint names is and how it moves, in ground axes.
struct FrameMotion {
    Mat3 R; // its axes (a point: its body's)
    Vec3 r; // position
    Vec3 v; // velocity
    Vec3 w; // angular velocity
};

/// What a kind's builder reads: the model, its symbols and the tree's frames.
class ConstraintContext {
public:
    ConstraintContext(const model::Model& m, Symbols& symbols,
                      const std::vector<FrameState>& frames)
        : model(m), symbols(symbols), frames(frames) {}
    /// The motion of a body's frame (ground: -1), a point or a flexible body's node.
    FrameMotion motion(const model::FrameRef& ref);

    const model::Model& model;
    Symbols& symbols;
    const std::vector<FrameState>& frames;

private:
    std::map<std::pair<int, int>, FrameState> nodes_;
};

/// One kind's rows, each list in the order of model::constraint_rows().
struct KindRows {
    std::vector<GiNaC::ex> holonomic; // Φ(q, t, u, p)
    std::vector<GiNaC::ex> speed;     // r(q, q', t, u, p), linear in q'
};

using ConstraintBuilder = KindRows (*)(const model::Constraint&, ConstraintContext&);

// The builders, one file each.
KindRows loop_rows(const model::Constraint& c, ConstraintContext& ctx);
KindRows relation_rows(const model::Constraint& c, ConstraintContext& ctx);
KindRows speed_rows(const model::Constraint& c, ConstraintContext& ctx);
KindRows rolling_rows(const model::Constraint& c, ConstraintContext& ctx);
KindRows prescribed_rows(const model::Constraint& c, ConstraintContext& ctx);

/// The builder of a kind (registry.cpp: one row per kind).
ConstraintBuilder constraint_builder(model::ConstraintKind kind);

/// Every row of the model's constraints, holonomic rows first (in declaration
/// order), then the velocity rows; each with Φ (holonomic), r = dΦ/dt or the
/// kind's speed row, and r_t, the explicit time part of dr/dt.
std::vector<ConstraintRow> derive_constraints(const model::Model& m, Symbols& symbols,
                                              const std::vector<FrameState>& frames);

} // namespace yamsc::symbolic
