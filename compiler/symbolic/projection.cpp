#include "symbolic/projection.hpp"

#include <set>

namespace yamsc::symbolic {

using namespace GiNaC;

namespace {

void accumulate(Inertia& into, const Inertia& add) {
    into.mass += add.mass;
    into.md = into.md + add.md;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) into.J.m[i][j] += add.J.m[i][j];
}

void accumulate(Wrench& into, const Wrench& add) {
    into.force = into.force + add.force;
    into.moment = into.moment + add.moment;
}

std::set<int> keys(const FrameState& f) {
    std::set<int> out;
    for (const auto& [r, v] : f.Jv) out.insert(r);
    for (const auto& [r, w] : f.Jw) out.insert(r);
    return out;
}

} // namespace

Projection::Projection(const model::Model& m, const std::vector<FrameState>& frames,
                       std::vector<FrameState> relative, std::vector<BodyTerms> terms,
                       Grouping grouping)
    : m_(m), frames_(frames), relative_(std::move(relative)), terms_(std::move(terms)) {
    const std::size_t nb = m_.bodies.size();
    anchors_.resize(m_.dofs.size());
    for (std::size_t b = 0; b < nb; ++b) {
        grouped_.push_back(grouping == Grouping::all ||
                           (grouping == Grouping::flexible && !terms_[b].modes.empty()));
        introduced_.push_back(keys(relative_[b]));
        for (int r : introduced_.back())
            anchors_[static_cast<std::size_t>(r)].push_back({int(b), false});
        // A body summed on its own adds its modes' terms itself.
        if (grouped_[b])
            for (const ModeTerms& mode : terms_[b].modes)
                anchors_[static_cast<std::size_t>(mode.dof)].push_back({int(b), true});
    }
    for (const auto& anchors : anchors_) {
        bool ok = true;
        for (std::size_t i = 0; i < anchors.size(); ++i)
            for (std::size_t j = i + 1; j < anchors.size(); ++j)
                ok = ok && !anchors_overlap(anchors[i], anchors[j]);
        composite_ok_.push_back(ok);
    }
    // Subtrees from the leaves up: a child's index is above its parent's.
    for (std::size_t b = 0; b < nb; ++b) {
        composite_.push_back(grouped_[b] ? terms_[b].inertia : Inertia{});
        loads_.push_back(grouped_[b] ? terms_[b].load : Wrench{});
    }
    for (std::size_t b = nb; b-- > 0;) {
        const int parent = m_.bodies[b].parent;
        if (parent < 0) continue;
        const auto p = static_cast<std::size_t>(parent);
        accumulate(composite_[p], to_parent(composite_[b], relative_[b].R, relative_[b].r));
        accumulate(loads_[p], to_parent(loads_[b], relative_[b].R, relative_[b].r));
    }
}

Projection::Partial Projection::partial(int body, int r) const {
    const FrameState& f = frames_[static_cast<std::size_t>(body)];
    Partial p;
    if (auto it = f.Jv.find(r); it != f.Jv.end()) {
        p.v = it->second;
        p.moves = true;
    }
    if (auto it = f.Jw.find(r); it != f.Jw.end()) {
        p.w = it->second;
        p.moves = true;
    }
    return p;
}

int Projection::mode(int body, int r) const {
    const auto& modes = terms_[static_cast<std::size_t>(body)].modes;
    for (std::size_t k = 0; k < modes.size(); ++k)
        if (modes[k].dof == r) return static_cast<int>(k);
    return -1;
}

bool Projection::in_subtree(int body, int root) const {
    while (body >= 0 && body != root) body = m_.bodies[static_cast<std::size_t>(body)].parent;
    return body == root;
}

bool Projection::anchors_overlap(const Anchor& a, const Anchor& b) const {
    // An anchor reaches its body's subtree through the joints, or only its body
    // elastically.
    const bool a_reaches_b = a.elastic ? a.body == b.body : in_subtree(b.body, a.body);
    const bool b_reaches_a = b.elastic ? a.body == b.body : in_subtree(a.body, b.body);
    return a_reaches_b || b_reaches_a;
}

bool Projection::projects_over(int s, int r) const {
    for (const Anchor& at : anchors_[static_cast<std::size_t>(s)]) {
        if (at.elastic) continue; // the body's own share, projected on r directly
        for (const Anchor& other : anchors_[static_cast<std::size_t>(r)]) {
            const bool same_joint = other.body == at.body && !other.elastic;
            if (!same_joint && in_subtree(other.body, at.body)) return false;
        }
    }
    return true;
}

ex Projection::share(const Anchor& at, int s, int r) {
    const BodyTerms& t = terms_[static_cast<std::size_t>(at.body)];
    const Partial pr = partial(at.body, r);
    if (at.elastic) {
        // Only the body itself: its mode s against r's rigid motion of the body
        // and, for another of its modes, the modal mass.
        const auto k = static_cast<std::size_t>(mode(at.body, s));
        ex sum = 0;
        if (const int parent = m_.bodies[static_cast<std::size_t>(at.body)].parent;
            pr.moves && parent >= 0 && !introduced_[static_cast<std::size_t>(at.body)].count(r)) {
            // r moves the body with its parent: project the mode's momentum moved to
            // the parent (one transform per mode instead of r's partials in the
            // body's axes, which nothing else in M and F needs).
            auto it = momentum_at_parent_.find(s);
            if (it == momentum_at_parent_.end()) {
                const FrameState& rel = relative_[static_cast<std::size_t>(at.body)];
                it = momentum_at_parent_
                         .emplace(s, to_parent(Wrench{t.modes[k].ct, t.modes[k].cr}, rel.R, rel.r))
                         .first;
            }
            const Partial pp = partial(parent, r);
            sum += dot(pp.v, it->second.force) + dot(pp.w, it->second.moment);
        } else if (pr.moves) {
            sum += dot(pr.v, t.modes[k].ct) + dot(pr.w, t.modes[k].cr);
        }
        if (const int l = mode(at.body, r); l >= 0) sum += t.Me[static_cast<std::size_t>(l)][k];
        return sum;
    }
    if (!pr.moves) return 0;
    auto it = momentum_.find({s, at.body});
    if (it == momentum_.end()) {
        const Partial ps = partial(at.body, s);
        it = momentum_
                 .emplace(std::make_pair(s, at.body),
                          composite_[static_cast<std::size_t>(at.body)].momentum(ps.v, ps.w))
                 .first;
    }
    return dot(pr.v, it->second.force) + dot(pr.w, it->second.moment);
}

ex Projection::mass(int r, int s) {
    exvector sum;
    for (std::size_t b = 0; b < terms_.size(); ++b)
        if (!grouped_[b]) sum.push_back(body_mass(b, r, s));
    const auto ur = static_cast<std::size_t>(r), us = static_cast<std::size_t>(s);
    bool projected = false;
    if (composite_ok_[ur] && composite_ok_[us]) {
        for (auto [anchored, other] : {std::pair{s, r}, std::pair{r, s}}) {
            if (!projects_over(anchored, other)) continue;
            for (const Anchor& at : anchors_[static_cast<std::size_t>(anchored)])
                sum.push_back(share(at, anchored, other));
            projected = true;
            break;
        }
    }
    for (std::size_t b = 0; !projected && b < terms_.size(); ++b)
        if (grouped_[b]) sum.push_back(body_mass(b, r, s));
    return sum.empty() ? ex(0) : ex(add(sum));
}

ex Projection::body_mass(std::size_t b, int r, int s) const {
    const int body = static_cast<int>(b);
    const Partial pr = partial(body, r), ps = partial(body, s);
    const int kr = mode(body, r), ks = mode(body, s);
    if ((!pr.moves && kr < 0) || (!ps.moves && ks < 0)) return 0;
    const BodyTerms& t = terms_[b];
    if (t.rigid) {
        // m vG_r · vG_s + ω_r · J_G ω_s with the partial velocities of the COM.
        const Vec3 vr = pr.v + cross(pr.w, t.rigid->com), vs = ps.v + cross(ps.w, t.rigid->com);
        return t.inertia.mass * dot(vr, vs) + dot(pr.w, t.rigid->JG * ps.w);
    }
    // The momentum of q'_s = 1 and its part along mode r.
    Wrench h = t.inertia.momentum(ps.v, ps.w);
    ex along_r = 0;
    if (ks >= 0) {
        const ModeTerms& m = t.modes[static_cast<std::size_t>(ks)];
        h.force = h.force + m.ct;
        h.moment = h.moment + m.cr;
    }
    if (kr >= 0) {
        const ModeTerms& m = t.modes[static_cast<std::size_t>(kr)];
        if (ps.moves) along_r += dot(m.ct, ps.v) + dot(m.cr, ps.w);
        if (ks >= 0) along_r += t.Me[static_cast<std::size_t>(kr)][static_cast<std::size_t>(ks)];
    }
    return dot(pr.v, h.force) + dot(pr.w, h.moment) + along_r;
}

ex Projection::body_force(std::size_t b, int r) const {
    const int body = static_cast<int>(b);
    ex sum = 0;
    const Partial p = partial(body, r);
    if (p.moves) sum += dot(p.v, terms_[b].load.force) + dot(p.w, terms_[b].load.moment);
    if (const int k = mode(body, r); k >= 0)
        sum += terms_[b].modes[static_cast<std::size_t>(k)].force;
    return sum;
}

ex Projection::force(int r) const {
    const auto ur = static_cast<std::size_t>(r);
    exvector sum;
    for (std::size_t b = 0; b < terms_.size(); ++b)
        if (!grouped_[b] || !composite_ok_[ur]) sum.push_back(body_force(b, r));
    for (const Anchor& at : anchors_[ur]) {
        if (!composite_ok_[ur]) break;
        const auto b = static_cast<std::size_t>(at.body);
        if (at.elastic) {
            sum.push_back(terms_[b].modes[static_cast<std::size_t>(mode(at.body, r))].force);
            continue;
        }
        const Partial p = partial(at.body, r);
        sum.push_back(dot(p.v, loads_[b].force) + dot(p.w, loads_[b].moment));
    }
    return sum.empty() ? ex(0) : ex(add(sum));
}

void add_mass_times(const std::vector<FrameState>& frames, const std::vector<BodyTerms>& bodies,
                    const std::vector<symbol>& a, std::vector<exvector>& terms) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const BodyTerms& t = bodies[b];
        const FrameState& f = frames[b];
        // The accelerations' velocity and angular velocity of the frame, and the
        // momentum rate they give (eq. A1 with q'' = a).
        Vec3 V, W;
        for (const auto& [s, v] : f.Jv) V = V + a[static_cast<std::size_t>(s)] * v;
        for (const auto& [s, w] : f.Jw) W = W + a[static_cast<std::size_t>(s)] * w;
        Wrench A;
        if (t.rigid) { // about the COM: fewer operations than the origin's inertia
            A.force = t.inertia.mass * (V + cross(W, t.rigid->com));
            A.moment = cross(t.rigid->com, A.force) + t.rigid->JG * W;
        } else {
            A = t.inertia.momentum(V, W);
        }
        for (const ModeTerms& m : t.modes) {
            const ex& as = a[static_cast<std::size_t>(m.dof)];
            A.force = A.force + as * m.ct;
            A.moment = A.moment + as * m.cr;
        }
        for (const auto& [r, v] : f.Jv)
            terms[static_cast<std::size_t>(r)].push_back(dot(v, A.force));
        for (const auto& [r, w] : f.Jw)
            terms[static_cast<std::size_t>(r)].push_back(dot(w, A.moment));
        for (std::size_t k = 0; k < t.modes.size(); ++k) {
            const ModeTerms& m = t.modes[k];
            exvector e{dot(m.ct, V), dot(m.cr, W)};
            for (std::size_t l = 0; l < t.modes.size(); ++l)
                e.push_back(t.Me[k][l] * a[static_cast<std::size_t>(t.modes[l].dof)]);
            terms[static_cast<std::size_t>(m.dof)].push_back(add(e));
        }
    }
}

} // namespace yamsc::symbolic
