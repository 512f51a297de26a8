#pragma once
// The OC3-Hywind spar as strip-theory members, from the published definition
// (Jonkman, "Definition of the Floating System for Phase IV of OC3",
// NREL/TP-500-47535, 2010): 120 m draft, 9.4 m diameter below 12 m depth, a taper
// to 6.5 m at 4 m depth, 6.5 m above up to 10 m; Cd 0.6, Ca 0.969954, Cp 1;
// water density 1025 kg/m^3. The body origin is at the still-water level.
#include <yamsc/hydro/strip_theory.hpp>

#include <cmath>
#include <vector>

namespace test {

inline constexpr double pi = 3.14159265358979323846;
inline constexpr double rho = 1025, g = 9.80665;
inline constexpr double ca = 0.969954, cd = 0.6;
/// The body frame at rest: no rotation, the origin at the still-water level.
inline constexpr double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
inline constexpr double at_rest[3] = {0, 0, 0};

inline yamsc::runtime::hydro::StripSetup oc3_spar(double division = 0.5) {
    using namespace yamsc::runtime::hydro;
    StripSetup s;
    s.water.density = rho;
    s.water.gravity = g;
    s.water.depth = 320;
    const StripCoefficients c{cd, ca, 1.0, 0.0, 1.0, 1.0};
    const double z[4] = {-120, -12, -4, 10};
    const double d[4] = {9.4, 9.4, 6.5, 6.5};
    for (int i = 0; i < 3; ++i) {
        StripMember m;
        m.end1 = {0, 0, z[i]};
        m.end2 = {0, 0, z[i + 1]};
        m.diameter1 = d[i];
        m.diameter2 = d[i + 1];
        m.c1 = m.c2 = c;
        m.division_size = division;
        s.members.push_back(m);
    }
    for (int i = 0; i < 18; ++i) s.frame_outputs.push_back(i);
    for (int i = 0; i < 6; ++i) s.loads.push_back(i);
    s.output_prefix = "strip_";
    return s;
}

/// The spar's volume below the still-water level, from its three sections.
inline double oc3_volume() {
    const double r1 = 4.7, r2 = 3.25;
    return pi * (r1 * r1 * 108 + 8 * (r1 * r1 + r1 * r2 + r2 * r2) / 3 + r2 * r2 * 4);
}

/// Its centre of buoyancy's depth (negative), from the sections' centroids.
inline double oc3_buoyancy_centre() {
    const double r1 = 4.7, r2 = 3.25;
    const double v1 = pi * r1 * r1 * 108, v3 = pi * r2 * r2 * 4;
    const double sum = r1 * r1 + r1 * r2 + r2 * r2;
    const double v2 = pi * 8 * sum / 3;
    const double z2 = -12 + 8 * (r1 * r1 + 2 * r1 * r2 + 3 * r2 * r2) / (4 * sum);
    return (v1 * -66 + v2 * z2 + v3 * -2) / (v1 + v2 + v3);
}

/// The 18 mesh outputs of a body frame: origin r, velocity v, angular velocity w,
/// then its axes (the columns of R) in ground components.
inline std::vector<double> frame(const double r[3], const double R[9], const double v[3] = nullptr,
                                 const double w[3] = nullptr) {
    std::vector<double> f(18, 0.0);
    for (int i = 0; i < 3; ++i) {
        f[static_cast<std::size_t>(i)] = r[i];
        if (v) f[static_cast<std::size_t>(3 + i)] = v[i];
        if (w) f[static_cast<std::size_t>(6 + i)] = w[i];
        for (int c = 0; c < 3; ++c) f[static_cast<std::size_t>(9 + 3 * c + i)] = R[3 * i + c];
    }
    return f;
}

/// Rotation by `angle` about the unit axis u (row-major).
inline void rotation(const double u[3], double angle, double R[9]) {
    const double c = std::cos(angle), s = std::sin(angle), k = 1 - c;
    R[0] = c + u[0] * u[0] * k;
    R[1] = u[0] * u[1] * k - u[2] * s;
    R[2] = u[0] * u[2] * k + u[1] * s;
    R[3] = u[1] * u[0] * k + u[2] * s;
    R[4] = c + u[1] * u[1] * k;
    R[5] = u[1] * u[2] * k - u[0] * s;
    R[6] = u[2] * u[0] * k - u[1] * s;
    R[7] = u[2] * u[1] * k + u[0] * s;
    R[8] = c + u[2] * u[2] * k;
}

struct Evaluation {
    std::vector<double> loads, out;
};
inline Evaluation evaluate(const yamsc::runtime::LoadBlock& b, const std::vector<double>& r,
                           double t = 0) {
    Evaluation e{std::vector<double>(6), std::vector<double>(b.output_names().size())};
    b.evaluate(t, nullptr, r.data(), e.loads.data(), nullptr, e.out.data());
    return e;
}

} // namespace test
