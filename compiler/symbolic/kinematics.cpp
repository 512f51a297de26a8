#include "symbolic/kinematics.hpp"

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

} // namespace

FrameState apply_step(const FrameState& f, const model::Step& step, Symbols& symbols) {
    FrameState n = f;
    const auto& dofs = symbols.dofs();
    switch (step.kind) {
    case model::Step::Kind::offset: {
        Vec3 c = to_ginac(step.vector, symbols);
        n.r = f.r + f.R * c;
        n.v = f.v + cross(f.w, c);
        n.a = f.a + cross(f.alpha, c) + cross(f.w, cross(f.w, c));
        for (const auto& [r, jw] : f.Jw) add_partial(n.Jv, r, cross(jw, c));
        return n;
    }
    case model::Step::Kind::translate: {
        Vec3 e = unit_axis(step, symbols);
        ex s = to_ginac(step.arg, symbols);
        ex sd = symbols.time_derivative(s, false);
        ex sdd = symbols.time_derivative(sd, false);
        Vec3 d = s * e;
        n.r = f.r + f.R * d;
        n.v = f.v + cross(f.w, d) + sd * e;
        n.a = f.a + cross(f.alpha, d) + cross(f.w, cross(f.w, d)) + (2 * sd) * cross(f.w, e) +
              sdd * e;
        for (const auto& [r, jw] : f.Jw) add_partial(n.Jv, r, cross(jw, d));
        for (std::size_t r = 0; r < dofs.size(); ++r) {
            ex ds = symbols.diff(s, dofs[r].q);
            if (!ds.is_zero()) add_partial(n.Jv, static_cast<int>(r), ds * e);
        }
        return n;
    }
    case model::Step::Kind::rotate: {
        Vec3 e = unit_axis(step, symbols);
        ex th = to_ginac(step.arg, symbols);
        ex thd = symbols.time_derivative(th, false);
        ex thdd = symbols.time_derivative(thd, false);
        Mat3 rot = rotation(e, cos(th), sin(th));
        auto to_new = [&](const Vec3& x) { return transpose_times(rot, x); };
        n.R = f.R * rot;
        Vec3 w_old_new = to_new(f.w);
        n.w = w_old_new + thd * e;
        n.v = to_new(f.v);
        n.alpha = to_new(f.alpha) + thdd * e + thd * cross(w_old_new, e);
        n.a = to_new(f.a);
        n.Jw.clear();
        n.Jv.clear();
        for (const auto& [r, jw] : f.Jw) n.Jw.emplace(r, to_new(jw));
        for (const auto& [r, jv] : f.Jv) n.Jv.emplace(r, to_new(jv));
        for (std::size_t r = 0; r < dofs.size(); ++r) {
            ex dth = symbols.diff(th, dofs[r].q);
            if (!dth.is_zero()) add_partial(n.Jw, static_cast<int>(r), dth * e);
        }
        return n;
    }
    }
    return n;
}

std::vector<FrameState> body_frames(const model::Model& m, Symbols& symbols) {
    std::vector<FrameState> frames;
    frames.reserve(m.bodies.size());
    for (const auto& b : m.bodies) {
        FrameState f =
            b.parent < 0 ? FrameState::ground() : frames[static_cast<std::size_t>(b.parent)];
        for (const auto& step : b.steps) f = apply_step(f, step, symbols);
        frames.push_back(std::move(f));
    }
    return frames;
}

} // namespace yamsc::symbolic
