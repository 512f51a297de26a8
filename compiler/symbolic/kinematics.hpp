#pragma once
// Kinematics of the body tree (paper eq. 1-3, 8), computed recursively from
// ground outwards, one elementary joint step at a time. Every vector is kept in
// the current frame's own axes ("primed" in the paper), which keeps expressions
// of deep chains small and shared. Velocities are kept with their partial
// velocities ∂v/∂q'_r, ∂ω/∂q'_r (Kane's Jacobians) and accelerations as their
// "bias" part, without q'' (the q'' part is Σ J_r q''_r).
#include "model/model.hpp"
#include "symbolic/expressions.hpp"

#include <map>

namespace yamsc::symbolic {

/// Position, orientation and motion of a frame.
struct FrameState {
    Mat3 R;                 // orientation: columns are the frame's axes in ground
    Vec3 r;                 // origin, ground axes
    Vec3 w;                 // angular velocity, own axes
    Vec3 v;                 // origin velocity, own axes
    Vec3 alpha;             // angular acceleration without q'' terms, own axes
    Vec3 a;                 // origin acceleration without q'' terms, own axes
    std::map<int, Vec3> Jw; // ∂ω/∂q'_r, own axes (only DOFs that move this frame)
    std::map<int, Vec3> Jv; // ∂v/∂q'_r of the origin, own axes

    static FrameState ground();
};

/// The frame of each body of the model, in the model's body order.
std::vector<FrameState> body_frames(const model::Model& m, Symbols& symbols);

/// Applies one joint step to a frame; `parent` is the body the joint hangs from
/// (needed by node steps).
FrameState apply_step(const FrameState& f, const model::Step& step, Symbols& symbols,
                      const model::Body* parent = nullptr);

/// Moves the origin by p (current axes) with rate pd, bias acceleration pdd (no q''
/// terms) and partials ∂p/∂q_r.
FrameState move_origin(const FrameState& f, const Vec3& p, const Vec3& pd, const Vec3& pdd,
                       const std::map<int, Vec3>& dp_dq);

/// Turns the frame by `rot` (columns: new axes in current axes) while it spins with
/// w_rel (new axes) and bias angular acceleration alpha_rel; ∂w_rel/∂q'_r given.
FrameState rotate_frame(const FrameState& f, const Mat3& rot, const Vec3& w_rel,
                        const Vec3& alpha_rel, const std::map<int, Vec3>& dw_dqd);

} // namespace yamsc::symbolic
