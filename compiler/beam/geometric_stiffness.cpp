#include "beam/geometric_stiffness.hpp"

namespace yamsc::beam {

namespace {

/// K(j,k) = integral of N Phi_j' . Phi_k' (eq. B5); symmetric by construction.
Matrix stiffness_for_load(const SampledBeam& b, const std::vector<double>& N) {
    const std::size_t nq = b.modes.size(), n = b.grid.size();
    Matrix K(nq, std::vector<double>(nq, 0.0));
    std::vector<double> f(n);
    for (std::size_t j = 0; j < nq; ++j)
        for (std::size_t k = j; k < nq; ++k) {
            for (std::size_t i = 0; i < n; ++i)
                f[i] = N[i] * dot(b.modes[j].slope[i], b.modes[k].slope[i]);
            K[j][k] = K[k][j] = b.grid.integrate(f);
        }
    return K;
}

} // namespace

GeometricStiffness geometric_stiffness(const SampledBeam& b) {
    const std::size_t n = b.grid.size();
    // Loads carried by the section at z: the mass outboard of it, and its first moment
    // S(z) = integral from z to L of m s0 (eq. C5).
    const std::vector<double> outboard_mass = b.grid.integral_to_tip(b.m);
    std::array<std::vector<double>, 3> S;
    for (std::size_t a = 0; a < 3; ++a) {
        std::vector<double> f(n);
        for (std::size_t i = 0; i < n; ++i) f[i] = b.m[i] * b.s0[i][a];
        S[a] = b.grid.integral_to_tip(f);
    }
    const std::size_t nq = b.modes.size();
    const Matrix zero(nq, std::vector<double>(nq, 0.0));
    GeometricStiffness K;
    std::vector<double> N(n);
    for (int alpha = 0; alpha < 3; ++alpha) {
        // eq. C3: a unit acceleration along +z pushes the outboard mass onto the
        // section: compression, N = -outboard mass. Transverse ones load nothing axially.
        if (alpha == 2) {
            for (std::size_t i = 0; i < n; ++i) N[i] = -outboard_mass[i];
            K.gt[2] = stiffness_for_load(b, N);
        } else {
            K.gt[static_cast<std::size_t>(alpha)] = zero;
        }
        // eq. C6: N = -e_z . (e_alpha x S)
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 Si{S[0][i], S[1][i], S[2][i]};
            N[i] = -cross(unit(alpha), Si)[2];
        }
        K.gr[static_cast<std::size_t>(alpha)] = stiffness_for_load(b, N);
        // eq. C5: N = -e_z . (e_alpha x (e_beta x S)); omega about x: N = +S_z, tension.
        for (int beta = 0; beta < 3; ++beta) {
            for (std::size_t i = 0; i < n; ++i) {
                const Vec3 Si{S[0][i], S[1][i], S[2][i]};
                N[i] = -cross(unit(alpha), cross(unit(beta), Si))[2];
            }
            K.gw[static_cast<std::size_t>(alpha)][static_cast<std::size_t>(beta)] =
                stiffness_for_load(b, N);
        }
    }
    return K;
}

std::vector<std::vector<std::vector<double>>> axial_shortening(const SampledBeam& b) {
    const std::size_t nq = b.modes.size(), n = b.grid.size();
    std::vector<std::vector<std::vector<double>>> out(nq, std::vector<std::vector<double>>(nq));
    std::vector<double> f(n);
    for (std::size_t j = 0; j < nq; ++j)
        for (std::size_t k = j; k < nq; ++k) {
            for (std::size_t i = 0; i < n; ++i)
                f[i] = -dot(b.modes[j].slope[i], b.modes[k].slope[i]);
            out[j][k] = out[k][j] = b.grid.running_integral(f);
        }
    return out;
}

} // namespace yamsc::beam
