#include "symbolic/kinematics.hpp"

#include "symbolic/sid_terms.hpp"

namespace yamsc::symbolic {

using namespace GiNaC;

FrameState FrameState::ground() {
    FrameState f;
    f.R = Mat3::identity();
    return f;
}

namespace {

/// Unit axis of a step.
Vec3 unit_axis(const model::Step& step, Symbols& symbols) {
    Vec3 e = to_ginac(step.vector, symbols);
    if (step.axis_index >= 0) return e; // exact ±1 on one axis
    ex norm = sqrt(dot(e, e));
    return pow(norm, -1) * e;
}

/// Rotation about unit axis e by angle θ (c = cos θ, s = sin θ): R = cI + s[e]x + (1-c)eeᵀ.
Mat3 rotation(const Vec3& e, const ex& c, const ex& s) {
    Mat3 R;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            R.m[i][j] = (1 - c) * e[i] * e[j] + (i == j ? c : ex(0));
    R.m[0][1] -= s * e[2];
    R.m[0][2] += s * e[1];
    R.m[1][0] += s * e[2];
    R.m[1][2] -= s * e[0];
    R.m[2][0] -= s * e[1];
    R.m[2][1] += s * e[0];
    return R;
}

void add_partial(std::map<int, Vec3>& J, int r, const Vec3& v) {
    auto it = J.find(r);
    if (it == J.end())
        J.emplace(r, v);
    else
        it->second = it->second + v;
}

/// Partials ∂s/∂q_r of a scalar joint argument, for every DOF it uses.
std::map<int, Vec3> partials_along(const ex& s, const Vec3& e, Symbols& symbols) {
    std::map<int, Vec3> out;
    const auto& dofs = symbols.dofs();
    for (std::size_t r = 0; r < dofs.size(); ++r) {
        ex ds = symbols.diff(s, dofs[r].q);
        if (!ds.is_zero()) out.emplace(static_cast<int>(r), ds * e);
    }
    return out;
}

/// Elementary rotation about the unit axis e by the angle th (a function of q, u, t).
FrameState rotate_about(const FrameState& f, const Vec3& e, const ex& th, Symbols& symbols) {
    ex thd = symbols.time_derivative(th, false);
    ex thdd = symbols.time_derivative(thd, false);
    return rotate_frame(f, rotation(e, cos(th), sin(th)), thd * e, thdd * e,
                        partials_along(th, e, symbols));
}

/// The elastic rotation θ of a node as the rotation nearest to I + [θ]× (its
/// orthonormal polar factor, ElastoDyn's small-angle rotation matrix): with
/// s = sqrt(1 + θ·θ), R = (I + [θ]×)/s + θθᵀ/(s(s+1)), a rotation by atan|θ|
/// about θ. I + [θ]× itself is not a rotation (its columns are √(1 + |θ|²)
/// long), and Kane's method on it gives M and F that no kinetic energy shares.
/// The angular velocity is R's own, vee(Rᵀ Ṙ) = W θ̇ in the new axes, with
/// W = I/s - θθᵀ/(s²(s+1)) - [θ]×/(s(s+1)), so M and F follow from one T.
FrameState rotate_small(const FrameState& f, const NodeMotion& node, Symbols& symbols) {
    const Vec3& th = node.theta;
    const ex s = sqrt(1 + dot(th, th));
    const ex a = pow(s, -1), c = pow(s * (s + 1), -1);
    Mat3 rot, W;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            const ex diagonal = i == j ? a : ex(0);
            rot.m[i][j] = diagonal + c * th[i] * th[j];
            W.m[i][j] = diagonal - a * c * th[i] * th[j];
        }
    // [θ]× entries: (i, j, k, sign) with [θ]×_ij = sign θ_k.
    const int skew[6][4] = {{0, 1, 2, -1}, {0, 2, 1, 1},  {1, 0, 2, 1},
                            {1, 2, 0, -1}, {2, 0, 1, -1}, {2, 1, 0, 1}};
    for (const auto& e : skew) {
        const auto i = static_cast<std::size_t>(e[0]), j = static_cast<std::size_t>(e[1]),
                   k = static_cast<std::size_t>(e[2]);
        rot.m[i][j] += e[3] * a * th[k];
        W.m[i][j] -= e[3] * c * th[k];
    }
    const Vec3 w_rel = W * node.thetad;
    Vec3 alpha_rel;
    for (std::size_t i = 0; i < 3; ++i) alpha_rel[i] = symbols.time_derivative(w_rel[i], false);
    std::map<int, Vec3> dw_dqd;
    for (const auto& [r, dth] : node.dtheta_dq) dw_dqd.emplace(r, W * dth);
    return rotate_frame(f, rot, w_rel, alpha_rel, dw_dqd);
}

} // namespace

FrameState move_origin(const FrameState& f, const Vec3& p, const Vec3& pd, const Vec3& pdd,
                       const std::map<int, Vec3>& dp_dq) {
    FrameState n = f;
    n.r = f.r + f.R * p;
    n.v = f.v + cross(f.w, p) + pd;
    n.a = f.a + cross(f.alpha, p) + cross(f.w, cross(f.w, p)) + 2 * cross(f.w, pd) + pdd;
    for (const auto& [r, jw] : f.Jw) add_partial(n.Jv, r, cross(jw, p));
    for (const auto& [r, jv] : dp_dq) add_partial(n.Jv, r, jv);
    return n;
}

FrameState rotate_frame(const FrameState& f, const Mat3& rot, const Vec3& w_rel,
                        const Vec3& alpha_rel, const std::map<int, Vec3>& dw_dqd) {
    FrameState n;
    auto to_new = [&](const Vec3& x) { return transpose_times(rot, x); };
    n.R = f.R * rot;
    n.r = f.r;
    Vec3 w_old_new = to_new(f.w);
    n.w = w_old_new + w_rel;
    n.v = to_new(f.v);
    n.alpha = to_new(f.alpha) + alpha_rel + cross(w_old_new, w_rel);
    n.a = to_new(f.a);
    for (const auto& [r, jw] : f.Jw) n.Jw.emplace(r, to_new(jw));
    for (const auto& [r, jv] : f.Jv) n.Jv.emplace(r, to_new(jv));
    for (const auto& [r, jw] : dw_dqd) add_partial(n.Jw, r, jw);
    return n;
}

FrameState apply_step(const FrameState& f, const model::Step& step, Symbols& symbols,
                      const model::Body* parent) {
    switch (step.kind) {
    case model::Step::Kind::offset: {
        Vec3 zero;
        return move_origin(f, to_ginac(step.vector, symbols), zero, zero, {});
    }
    case model::Step::Kind::translate: {
        Vec3 e = unit_axis(step, symbols);
        ex s = to_ginac(step.arg, symbols);
        ex sd = symbols.time_derivative(s, false);
        ex sdd = symbols.time_derivative(sd, false);
        return move_origin(f, s * e, sd * e, sdd * e, partials_along(s, e, symbols));
    }
    case model::Step::Kind::rotate:
        return rotate_about(f, unit_axis(step, symbols), to_ginac(step.arg, symbols), symbols);
    case model::Step::Kind::node: {
        if (!parent || !parent->flex)
            throw diag::InternalError("a node step without a flexible parent body");
        NodeMotion node = node_motion(*parent, step.node, symbols);
        FrameState n = move_origin(f, node.p, node.pd, node.pdd, node.dp_dq);
        if (step.exact_rotation) {
            // Rotation matrices of the slopes, each about an axis of the frame the
            // previous one left, in the model's order (about x, then y, then z unless
            // it says otherwise): the orders differ at second order in the slopes.
            for (int axis : step.rotation_order) {
                const auto i = static_cast<std::size_t>(axis);
                if (node.theta[i].is_zero()) continue;
                Vec3 e;
                e[i] = 1;
                n = rotate_about(n, e, node.theta[i], symbols);
            }
        } else if (!(node.theta[0].is_zero() && node.theta[1].is_zero() &&
                     node.theta[2].is_zero())) {
            n = rotate_small(n, node, symbols);
        }
        if (node.orientation) n = rotate_frame(n, *node.orientation, Vec3{}, Vec3{}, {});
        return n;
    }
    }
    return f;
}

std::vector<FrameState> body_frames(const model::Model& m, Symbols& symbols) {
    std::vector<FrameState> frames;
    frames.reserve(m.bodies.size());
    for (const auto& b : m.bodies) {
        FrameState f =
            b.parent < 0 ? FrameState::ground() : frames[static_cast<std::size_t>(b.parent)];
        const model::Body* parent =
            b.parent < 0 ? nullptr : &m.bodies[static_cast<std::size_t>(b.parent)];
        for (const auto& step : b.steps) f = apply_step(f, step, symbols, parent);
        frames.push_back(std::move(f));
    }
    return frames;
}

} // namespace yamsc::symbolic
