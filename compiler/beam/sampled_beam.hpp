#pragma once
// A beam's properties and shape functions sampled on its integration grid: the input
// of every shape integral (paper Appendix A-C). Internal to beam/.
#include "beam/beam.hpp"
#include "beam/grid.hpp"
#include "beam/vec3.hpp"

namespace yamsc::beam {

struct SampledMode {
    std::vector<Vec3> phi;       // Phi_j(z): displacement per unit q_j, body axes
    std::vector<Vec3> slope;     // dPhi_j/dz
    std::vector<Vec3> curvature; // d2Phi_j/dz2
};

struct SampledBeam {
    Grid grid;
    std::vector<double> m;          // mass per length, kg/m
    std::vector<double> EI_x, EI_y; // bending stiffness about the principal axes
    std::vector<double> twist;      // rotation of the principal axes about z, rad
    std::vector<SampledMode> modes; // in SID order
    std::vector<Vec3> s0;           // undeformed position (0, 0, z)
};

/// The integral of f(i) dm over the beam, f: grid point index -> double, Vec3 or Mat3.
template <class F> auto integrate_dm(const SampledBeam& b, F f) {
    decltype(f(std::size_t{0})) sum{};
    const std::vector<double>& w = b.grid.weights();
    for (std::size_t i = 0; i < w.size(); ++i)
        if (w[i] != 0) sum = sum + (w[i] * b.m[i]) * f(i);
    return sum;
}

/// Samples `beam` (which must pass check_beam) on its integration grid.
SampledBeam sample_beam(const Beam& beam);

} // namespace yamsc::beam
