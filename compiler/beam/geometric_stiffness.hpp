#pragma once
// Unit geometric stiffness matrices of a beam along z (paper Appendix C2, eq. C3,
// C5, C6), with the PHYSICAL sign: positive axial load N = tension = stiffening.
// K(j,k) = integral of N(z) Phi_j'(z) . Phi_k'(z) dz (eq. B5 without the boundary
// term, which vanishes at the clamped root and the free tip where N = 0).
#include "beam/sampled_beam.hpp"

namespace yamsc::beam {

using Matrix = std::vector<std::vector<double>>; // nq x nq

struct GeometricStiffness {
    std::array<Matrix, 3> gt; // K_gt,alpha: unit acceleration of the body along alpha
    std::array<Matrix, 3> gr; // K_gr,alpha: unit angular acceleration about alpha
    std::array<std::array<Matrix, 3>, 3> gw; // K_gw,alpha,beta: unit omega_alpha omega_beta
};

GeometricStiffness geometric_stiffness(const SampledBeam& b);

/// The axial shortening of the beam at every grid point: -integral from 0 to z of
/// Phi_j' . Phi_k' (d2 u_z / dq_j dq_k), as shortening[j][k][point].
std::vector<std::vector<std::vector<double>>> axial_shortening(const SampledBeam& b);

} // namespace yamsc::beam
