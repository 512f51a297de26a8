#include "beam/make_sid.hpp"

#include "beam/geometric_stiffness.hpp"
#include "beam/shape_integrals.hpp"
#include "beam/sid_nodes.hpp"
#include "diag/diagnostics.hpp"

#include <cmath>

namespace yamsc::beam {

std::optional<std::string> check_beam(const Beam& beam) {
    if (!(beam.length > 0) || !std::isfinite(beam.length)) return "the beam length must be > 0";
    if (beam.integration_stations < 2) return "a beam needs at least 2 integration stations";
    if (beam.integration_stations > 100000) return "too many integration stations (at most 100000)";
    if (beam.elements < 0 || beam.elements > 100000)
        return "the number of elements must be 1 to 100000 (0: Gauss integration)";
    if (beam.stations.empty()) return "a beam needs at least one station";
    for (std::size_t i = 0; i < beam.stations.size(); ++i) {
        const Station& s = beam.stations[i];
        if (!(s.s >= 0 && s.s <= 1)) return "station fractions must lie in [0, 1]";
        if (i > 0 && !(s.s > beam.stations[i - 1].s))
            return "station fractions must be strictly increasing";
        if (!(s.mass_per_length >= 0) || !(s.EI_x >= 0) || !(s.EI_y >= 0) ||
            !std::isfinite(s.mass_per_length + s.EI_x + s.EI_y + s.twist))
            return "masses and stiffnesses must be finite and >= 0";
    }
    for (const Mode& m : beam.modes) {
        if (m.direction != 0 && m.direction != 1)
            return "mode '" + m.name + "': the direction must be x or y";
        if (m.coeffs.empty()) return "mode '" + m.name + "' has no shape coefficients";
        for (double c : m.coeffs)
            if (!std::isfinite(c)) return "mode '" + m.name + "' has a non-finite coefficient";
        if (!(m.damping_ratio >= 0) || !(m.stiffness_tuner > 0))
            return "mode '" + m.name + "': damping must be >= 0 and the stiffness tuner > 0";
    }
    return std::nullopt;
}

namespace {

/// ElastoDyn's damping (CBF, CBE, CTFA, CTSS in its `Coeff`): the full matrix
/// D(j,k) = 2 zeta_k Ke(j,k) / omega_k, omega_k = sqrt(Ke(k,k) / M_k) with the generalized
/// mass M_k of the untwisted polynomial shape (sum of m phi_k^2 over the elements).
/// Not symmetric when two modes of one direction couple through Ke (flap 1 and 2).
void elastodyn_damping(const Beam& beam, const SampledBeam& b, sid::Sid& sid) {
    const int nq = sid.nq;
    sid.De = sid::Taylor::zeros(0, nq, nq, nq, 3);
    std::vector<double> omega(static_cast<std::size_t>(nq));
    for (std::size_t k = 0; k < omega.size(); ++k) {
        const std::vector<double>& c = beam.modes[k].coeffs;
        const double M = integrate_dm(b, [&](std::size_t i) {
            double phi = 0;
            for (std::size_t p = 0; p < c.size(); ++p)
                phi += c[p] * std::pow(b.grid.z()[i] / beam.length, static_cast<double>(p));
            return phi * phi;
        });
        omega[k] = std::sqrt(sid.Ke.at0(static_cast<int>(k), static_cast<int>(k)) / M);
    }
    for (int j = 0; j < nq; ++j)
        for (int k = 0; k < nq; ++k)
            sid.De.at0(j, k) = 2 * beam.modes[static_cast<std::size_t>(k)].damping_ratio *
                               sid.Ke.at0(j, k) / omega[static_cast<std::size_t>(k)];
}

/// Ke per eq. B2, with the curvature split on the twisted principal axes:
/// EI_y resists curvature along the first axis (x without twist), EI_x along the second.
/// ElastoDyn's stiffness tuners scale Ke(j,k) by sqrt(t_j t_k).
void add_stiffness_and_damping(const Beam& beam, const SampledBeam& b, sid::Sid& sid) {
    const int nq = sid.nq;
    sid.Ke = sid::Taylor::zeros(0, nq, nq, nq, 2);
    sid.De = sid::Taylor::zeros(0, nq, nq, nq, 1);
    std::vector<double> f(b.grid.size());
    for (int j = 0; j < nq; ++j)
        for (int k = j; k < nq; ++k) {
            const auto& cj = b.modes[static_cast<std::size_t>(j)].curvature;
            const auto& ck = b.modes[static_cast<std::size_t>(k)].curvature;
            for (std::size_t i = 0; i < f.size(); ++i) {
                const double c = std::cos(b.twist[i]), s = std::sin(b.twist[i]);
                const Vec3 e1{c, s, 0}, e2{-s, c, 0};
                f[i] = b.EI_y[i] * dot(e1, cj[i]) * dot(e1, ck[i]) +
                       b.EI_x[i] * dot(e2, cj[i]) * dot(e2, ck[i]);
            }
            const double tune = std::sqrt(beam.modes[static_cast<std::size_t>(j)].stiffness_tuner *
                                          beam.modes[static_cast<std::size_t>(k)].stiffness_tuner);
            sid.Ke.at0(j, k) = sid.Ke.at0(k, j) = tune * b.grid.integrate(f);
        }
    if (beam.elements > 0) {
        elastodyn_damping(beam, b, sid);
        return;
    }
    // Modal damping (paper B4): D_jj = 2 zeta_j sqrt(K_jj M_jj) = 2 zeta_j M_jj omega_j.
    for (int j = 0; j < nq; ++j)
        sid.De.at0(j, j) = 2 * beam.modes[static_cast<std::size_t>(j)].damping_ratio *
                           std::sqrt(sid.Ke.at0(j, j) * sid.Me.at0(j, j));
}

/// The unit geometric stiffness matrices go into the first-order terms (paper D3):
/// Ct1 = K_gt, Cr1 += K_gr, Oe1 += K_gw in the 6-column layout of eq. A14.
void add_geometric_stiffness(const SampledBeam& b, sid::Sid& sid) {
    const GeometricStiffness K = geometric_stiffness(b);
    const int cols[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
    for (int j = 0; j < sid.nq; ++j)
        for (int k = 0; k < sid.nq; ++k) {
            const auto jj = static_cast<std::size_t>(j), kk = static_cast<std::size_t>(k);
            for (std::size_t a = 0; a < 3; ++a) {
                sid.Ct.at1(j, static_cast<int>(a), k) = K.gt[a][jj][kk];
                sid.Cr.at1(j, static_cast<int>(a), k) += K.gr[a][jj][kk];
            }
            for (int c = 0; c < 6; ++c) {
                const auto a = static_cast<std::size_t>(cols[c][0]);
                const auto d = static_cast<std::size_t>(cols[c][1]);
                double v = K.gw[a][d][jj][kk];
                if (a != d) v += K.gw[d][a][jj][kk];
                sid.Oe.at1(j, c, k) += v;
            }
        }
}

} // namespace

sid::Sid make_sid(const Beam& beam) {
    if (auto problem = check_beam(beam)) throw diag::InternalError("make_sid: " + *problem);
    const SampledBeam b = sample_beam(beam);
    sid::Sid sid;
    sid.nq = static_cast<int>(beam.modes.size());
    for (const Mode& m : beam.modes) sid.mode_names.push_back(m.name);
    add_inertia_integrals(b, sid);
    add_stiffness_and_damping(beam, b, sid);
    add_geometric_stiffness(b, sid);
    sid.ksigma = sid::Taylor::zeros(0, sid.nq, 1, sid.nq, 0); // stiffening is in the 1-terms
    add_nodes(b, sid);
    return sid;
}

sid::Sid make_section_sid(const Beam& beam, int node) {
    if (auto problem = check_beam(beam)) throw diag::InternalError("make_section_sid: " + *problem);
    SampledBeam b = sample_beam(beam);
    const std::vector<std::size_t>& nodes = b.grid.nodes();
    if (node < 0 || static_cast<std::size_t>(node) >= nodes.size())
        throw diag::InternalError("make_section_sid: no node " + std::to_string(node));
    // The part beyond the cut is the beam with no mass inboard of it: every
    // integral (the axial loads of the geometric stiffness too) then runs over it
    // alone, with the positions and shapes of the whole beam.
    const std::size_t cut = nodes[static_cast<std::size_t>(node)];
    for (std::size_t i = 0; i < cut; ++i) b.m[i] = 0;
    const double w = b.grid.weights()[cut];
    if (w > 0) {
        // ElastoDyn's gauge on an element centre (its TwHt/Spn loads): half the
        // element is beyond the cut, moving with the node, its arm a quarter of the
        // element along the undeformed axis.
        b.m[cut] *= 0.5;
        b.s0[cut][2] += 0.25 * w;
    }
    sid::Sid sid;
    sid.nq = static_cast<int>(beam.modes.size());
    for (const Mode& m : beam.modes) sid.mode_names.push_back(m.name);
    add_inertia_integrals(b, sid);
    add_geometric_stiffness(b, sid);
    // Elastic forces are internal to the part: only the inertia terms are used.
    sid.Ke = sid::Taylor::zeros(0, sid.nq, sid.nq, sid.nq, 2);
    sid.De = sid::Taylor::zeros(0, sid.nq, sid.nq, sid.nq, 1);
    sid.ksigma = sid::Taylor::zeros(0, sid.nq, 1, sid.nq, 0);
    return sid;
}

} // namespace yamsc::beam
