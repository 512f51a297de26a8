#include "beam/shape_integrals.hpp"

namespace yamsc::beam {

std::array<double, 6> oe_layout(const Mat3& o) {
    return {o[0][0], o[1][1], o[2][2], o[0][1] + o[1][0], o[1][2] + o[2][1], o[0][2] + o[2][0]};
}

namespace {

void add_rigid_terms(const SampledBeam& b, sid::Sid& sid) {
    const int nq = sid.nq;
    sid.mass = integrate_dm(b, [](std::size_t) { return 1.0; });
    // md_cm = integral of s_P dm (eq. A3), s_P = s0 + Phi q
    sid.md_cm = sid::Taylor::zeros(1, 3, 1, nq);
    const Vec3 first = integrate_dm(b, [&](std::size_t i) { return b.s0[i]; });
    for (int a = 0; a < 3; ++a) sid.md_cm.at0(a, 0) = first[a];
    // J = -integral of skew(s_P) skew(s_P) dm (eq. A4)
    sid.J = sid::Taylor::zeros(1, 3, 3, nq, 2);
    const Mat3 J0 =
        integrate_dm(b, [&](std::size_t i) { return -1.0 * (skew(b.s0[i]) * skew(b.s0[i])); });
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) sid.J.at0(r, c) = J0[r][c];
    for (int k = 0; k < nq; ++k) {
        const SampledMode& mk = b.modes[static_cast<std::size_t>(k)];
        const Vec3 md1 = integrate_dm(b, [&](std::size_t i) { return mk.phi[i]; });
        const Mat3 J1 = integrate_dm(b, [&](std::size_t i) {
            const Mat3 s = skew(b.s0[i]), p = skew(mk.phi[i]);
            return -1.0 * (s * p + p * s);
        });
        for (int r = 0; r < 3; ++r) {
            sid.md_cm.at1(r, 0, k) = md1[r];
            for (int c = 0; c < 3; ++c) sid.J.at1(r, c, k) = J1[r][c];
        }
    }
}

void add_elastic_terms(const SampledBeam& b, sid::Sid& sid) {
    const int nq = sid.nq;
    sid.Ct = sid::Taylor::zeros(1, nq, 3, nq);
    sid.Cr = sid::Taylor::zeros(1, nq, 3, nq);
    sid.Me = sid::Taylor::zeros(0, nq, nq, nq, 2);
    sid.Gr = sid::Taylor::zeros(0, 3, 3 * nq, nq);
    sid.Ge = sid::Taylor::zeros(0, nq, 3 * nq, nq);
    sid.Oe = sid::Taylor::zeros(1, nq, 6, nq);
    for (int j = 0; j < nq; ++j) {
        const SampledMode& mj = b.modes[static_cast<std::size_t>(j)];
        // Ct = M_ex = integral of Phi dm (eq. A6); Cr = M_etheta (eq. A5)
        const Vec3 ct = integrate_dm(b, [&](std::size_t i) { return mj.phi[i]; });
        const Vec3 cr = integrate_dm(b, [&](std::size_t i) { return cross(b.s0[i], mj.phi[i]); });
        // Gr_j = -2 integral of skew(s_P) skew(Phi_j) dm (eq. A11), zeroth order
        const Mat3 gr = integrate_dm(
            b, [&](std::size_t i) { return -2.0 * (skew(b.s0[i]) * skew(mj.phi[i])); });
        // O_e,j = integral of skew(Phi_j) skew(s_P) dm (eq. A12, A14)
        const auto oe0 = oe_layout(
            integrate_dm(b, [&](std::size_t i) { return skew(mj.phi[i]) * skew(b.s0[i]); }));
        for (int a = 0; a < 3; ++a) {
            sid.Ct.at0(j, a) = ct[a];
            sid.Cr.at0(j, a) = cr[a];
            for (int c = 0; c < 3; ++c) sid.Gr.at0(a, 3 * j + c) = gr[a][c];
        }
        for (int c = 0; c < 6; ++c) sid.Oe.at0(j, c) = oe0[static_cast<std::size_t>(c)];
        for (int k = 0; k < nq; ++k) {
            const SampledMode& mk = b.modes[static_cast<std::size_t>(k)];
            // Me = integral of Phi_j . Phi_k dm (eq. A7, B1)
            sid.Me.at0(j, k) =
                integrate_dm(b, [&](std::size_t i) { return dot(mj.phi[i], mk.phi[i]); });
            // Ge_j, row k: -2 integral of Phi_k^T skew(Phi_j) dm (eq. A13)
            const Vec3 ge = integrate_dm(
                b, [&](std::size_t i) { return -2.0 * row_times(mk.phi[i], skew(mj.phi[i])); });
            // first order of Cr: s_P -> Phi_k
            const Vec3 cr1 =
                integrate_dm(b, [&](std::size_t i) { return cross(mk.phi[i], mj.phi[i]); });
            // first order of O_e,j: s_P -> Phi_k
            const auto oe1 = oe_layout(
                integrate_dm(b, [&](std::size_t i) { return skew(mj.phi[i]) * skew(mk.phi[i]); }));
            for (int a = 0; a < 3; ++a) {
                sid.Ge.at0(k, 3 * j + a) = ge[a];
                sid.Cr.at1(j, a, k) = cr1[a];
            }
            for (int c = 0; c < 6; ++c) sid.Oe.at1(j, c, k) = oe1[static_cast<std::size_t>(c)];
        }
    }
    // The quadrature computes Me(j,k) and Me(k,j) identically; keep it exactly symmetric.
    for (int j = 0; j < nq; ++j)
        for (int k = 0; k < j; ++k) sid.Me.at0(j, k) = sid.Me.at0(k, j);
}

} // namespace

void add_inertia_integrals(const SampledBeam& b, sid::Sid& sid) {
    add_rigid_terms(b, sid);
    add_elastic_terms(b, sid);
}

} // namespace yamsc::beam
