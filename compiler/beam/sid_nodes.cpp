#include "beam/sid_nodes.hpp"

#include "beam/geometric_stiffness.hpp"

namespace yamsc::beam {

namespace {

/// Small rotation per unit q (paper D2: rotation field I + skew(Psi q)): a slope along
/// x turns the section about +y, a slope along y turns it about -x: psi = e_z x Phi'.
Vec3 rotation(const Vec3& slope) {
    return cross(unit(2), slope);
}

} // namespace

void add_nodes(const SampledBeam& b, sid::Sid& sid) {
    const int nq = sid.nq;
    const auto shortening = axial_shortening(b);
    int id = 1;
    for (std::size_t i : b.grid.nodes()) {
        sid::Node node;
        node.id = id++;
        node.rframe = "body ref";
        node.origin = sid::Taylor::zeros(1, 3, 1, nq);
        node.phi = sid::Taylor::zeros(1, 3, nq, nq);
        node.psi = sid::Taylor::zeros(0, 3, nq, nq);
        node.ap = sid::Taylor::zeros(1, 3, 3, nq);
        for (int a = 0; a < 3; ++a) {
            node.origin.at0(a, 0) = b.s0[i][a];
            node.ap.at0(a, a) = 1;
        }
        for (int j = 0; j < nq; ++j) {
            const SampledMode& mj = b.modes[static_cast<std::size_t>(j)];
            const Vec3 psi = rotation(mj.slope[i]);
            const Mat3 spsi = skew(psi);
            for (int a = 0; a < 3; ++a) {
                node.origin.at1(a, 0, j) = mj.phi[i][a];
                node.phi.at0(a, j) = mj.phi[i][a];
                node.psi.at0(a, j) = psi[a];
                for (int c = 0; c < 3; ++c) node.ap.at1(a, c, j) = spsi[a][c];
            }
            // phi1: the node's axial shortening d2u_z/dq_j dq_k, so that a load carried
            // at the node does work on it: the geometric stiffness K_gF (eq. C4, D3).
            for (int k = 0; k < nq; ++k)
                node.phi.at1(2, j, k) =
                    shortening[static_cast<std::size_t>(j)][static_cast<std::size_t>(k)][i];
        }
        sid.nodes.push_back(std::move(node));
    }
}

} // namespace yamsc::beam
