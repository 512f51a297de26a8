#include "symbolic/reactions.hpp"

#include "diag/errors.hpp"
#include "symbolic/flexible_body.hpp"

#include <utility>

namespace yamsc::symbolic {

using namespace GiNaC;

Mat3 inertia_tensor(const model::Body& b, const Symbols& s) {
    std::array<ex, 6> I;
    for (std::size_t i = 0; i < 6; ++i) I[i] = to_ginac(b.inertia[i], s);
    Mat3 J;
    J.m = {{{I[0], I[3], I[5]}, {I[3], I[1], I[4]}, {I[5], I[4], I[2]}}};
    return J;
}

Reactions::Reactions(const model::Model& m, const std::vector<FrameState>& frames,
                     const Symbols& symbols, std::vector<Wrench> applied)
    : m_(m), frames_(frames), symbols_(symbols), applied_(std::move(applied)), loads_(applied_) {
    for (const auto& d : symbols.dofs()) qdd_.emplace_back(d.qdd);
    for (std::size_t b = 0; b < m_.bodies.size(); ++b) {
        const Wrench w = load(b);
        loads_[b].force = loads_[b].force + w.force;
        loads_[b].moment = loads_[b].moment + w.moment;
    }
}

Wrench Reactions::load(std::size_t b) const {
    const model::Body& body = m_.bodies[b];
    const FrameState& f = frames_[b];
    const Vec3 g = transpose_times(f.R, to_ginac(m_.gravity, symbols_));
    if (body.flex) {
        auto [force, moment] = flexible_body_wrench(body, f, g, symbols_, qdd_);
        return {force, moment};
    }
    // The rigid body's terms of Kane's equations, with the q'' parts of the
    // accelerations (Σ_r J_r q''_r) put back: m g - m a_G and -J α - ω × J ω.
    const ex mass = to_ginac(body.mass, symbols_);
    const Vec3 c = to_ginac(body.com, symbols_);
    const Mat3 J = inertia_tensor(body, symbols_);
    Vec3 aG = f.a + cross(f.alpha, c) + cross(f.w, cross(f.w, c));
    Vec3 alpha = f.alpha;
    for (const auto& [r, jv] : f.Jv) aG = aG + qdd_[static_cast<std::size_t>(r)] * jv;
    for (const auto& [r, jw] : f.Jw) {
        aG = aG + qdd_[static_cast<std::size_t>(r)] * cross(jw, c);
        alpha = alpha + qdd_[static_cast<std::size_t>(r)] * jw;
    }
    Wrench w;
    w.force = mass * g - mass * aG;
    w.moment = cross(c, w.force) - J * alpha - cross(f.w, J * f.w);
    return w;
}

bool Reactions::carried_by(int i, int root) const {
    while (i >= 0 && i != root) i = m_.bodies[static_cast<std::size_t>(i)].parent;
    return i == root;
}

const Wrench& Reactions::of(int body) {
    auto it = done_.find(body);
    if (it != done_.end()) return it->second;
    // The joint supplies what the loads on the carried bodies leave of their
    // momentum rates: minus the sum of the loads, moments about the body's origin.
    const Vec3& origin = frames_[static_cast<std::size_t>(body)].r;
    Wrench total;
    for (std::size_t i = static_cast<std::size_t>(body); i < m_.bodies.size(); ++i) {
        if (!carried_by(static_cast<int>(i), body)) continue; // parents come first
        const FrameState& f = frames_[i];
        const Vec3 force = f.R * loads_[i].force;
        total.force = total.force - force;
        total.moment = total.moment - f.R * loads_[i].moment - cross(f.r - origin, force);
    }
    return done_.emplace(body, total).first->second;
}

/// The SID node a body's joint starts at on its flexible parent, -1 for none
/// (the parent's frame: its root).
static int attachment_node(const model::Body& child) {
    if (child.steps.empty() || child.steps.front().kind != model::Step::Kind::node) return -1;
    return child.steps.front().node;
}

const Wrench& Reactions::section(int body, int node, const FrameState& cut) {
    auto it = sections_.find({body, node});
    if (it != sections_.end()) return it->second;
    const auto b = static_cast<std::size_t>(body);
    const model::Body& whole = m_.bodies[b];
    if (!whole.flex || !whole.flex->sections.count(node))
        throw diag::InternalError("a section without its integrals: " + whole.name);
    // The part beyond the cut is the body with the shape integrals of that part:
    // its momentum rate and weight by the same formulas as the whole body's.
    model::Body part = whole;
    part.flex->sid = whole.flex->sections.at(node);
    const FrameState& f = frames_[b];
    const Vec3 g = transpose_times(f.R, to_ginac(m_.gravity, symbols_));
    auto [force, moment] = flexible_body_wrench(part, f, g, symbols_, qdd_);
    const bool root = node == 0; // what acts on the body's frame acts on its root
    if (root) {
        force = force + applied_[b].force;
        moment = moment + applied_[b].moment;
    }
    const Vec3& P = cut.r;
    const Vec3 F = f.R * force;
    Wrench total;
    total.force = -F;
    total.moment = -(f.R * moment) - cross(f.r - P, F);
    // Every body attached beyond the cut (at a node at or past it, or to the
    // frame when cutting at the root) through its joint's reaction.
    for (std::size_t i = b + 1; i < m_.bodies.size(); ++i) {
        const model::Body& child = m_.bodies[i];
        if (child.parent != body) continue;
        const int at = attachment_node(child);
        if (!(at >= node || (root && at < 0))) continue;
        const Wrench& w = of(static_cast<int>(i));
        total.force = total.force + w.force;
        total.moment = total.moment + w.moment + cross(frames_[i].r - P, w.force);
    }
    return sections_.emplace(std::make_pair(body, node), total).first->second;
}

} // namespace yamsc::symbolic
