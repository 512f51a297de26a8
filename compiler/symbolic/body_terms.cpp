#include "symbolic/body_terms.hpp"

#include "symbolic/reactions.hpp"

namespace yamsc::symbolic {

using namespace GiNaC;

namespace {

/// a bᵀ + b aᵀ.
Mat3 symmetric_outer(const Vec3& a, const Vec3& b) {
    Mat3 r;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) r.m[i][j] = a[i] * b[j] + b[i] * a[j];
    return r;
}

/// A moved by s I + k (a bᵀ + b aᵀ): the parallel-axis terms.
Mat3 shifted(const Mat3& A, const ex& s, const ex& k, const Mat3& outer) {
    Mat3 r;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            r.m[i][j] = A.m[i][j] + (i == j ? s : ex(0)) + k * outer.m[i][j];
    return r;
}

} // namespace

Wrench Inertia::momentum(const Vec3& v, const Vec3& w) const {
    return {mass * v + cross(w, md), cross(md, v) + J * w};
}

BodyTerms rigid_body_terms(const model::Body& body, const FrameState& f, const Vec3& g,
                           const Symbols& symbols) {
    const ex mass = to_ginac(body.mass, symbols);
    const Vec3 c = to_ginac(body.com, symbols);
    const Mat3 JG = inertia_tensor(body, symbols);
    BodyTerms t;
    // About the origin: J = J_G + m ((c·c) I - c cᵀ).
    t.inertia.mass = mass;
    t.inertia.md = mass * c;
    t.inertia.J = shifted(JG, mass * dot(c, c), -mass / 2, symmetric_outer(c, c));
    t.rigid = RigidInertia{c, JG};
    // Gravity and the inertial force at the COM, the inertial torque (eq. 6), as a
    // wrench about the origin.
    const Vec3 aG = f.a + cross(f.alpha, c) + cross(f.w, cross(f.w, c));
    t.load.force = mass * g - mass * aG;
    t.load.moment = cross(c, t.load.force) - JG * f.alpha - cross(f.w, JG * f.w);
    return t;
}

Inertia to_parent(const Inertia& inertia, const Mat3& R, const Vec3& p) {
    // J_p = R J Rᵀ + m ((p·p) I - p pᵀ) + 2 (p·md') I - (md' pᵀ + p md'ᵀ), md' = R md.
    Inertia out;
    out.mass = inertia.mass;
    const Vec3 md = R * inertia.md;
    out.md = inertia.mass * p + md;
    Mat3 RJ = R * inertia.J, RJRt;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i; j < 3; ++j) {
            RJRt.m[i][j] = RJ.m[i][0] * R.m[j][0] + RJ.m[i][1] * R.m[j][1] + RJ.m[i][2] * R.m[j][2];
            RJRt.m[j][i] = RJRt.m[i][j];
        }
    const Mat3 with_mass =
        shifted(RJRt, inertia.mass * dot(p, p), -inertia.mass / 2, symmetric_outer(p, p));
    out.J = shifted(with_mass, 2 * dot(p, md), -1, symmetric_outer(md, p));
    return out;
}

Wrench to_parent(const Wrench& w, const Mat3& R, const Vec3& p) {
    const Vec3 force = R * w.force;
    return {force, R * w.moment + cross(p, force)};
}

} // namespace yamsc::symbolic
