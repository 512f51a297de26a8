#pragma once
// NWTC's Euler angles as AeroDyn uses them to read orientations (NWTC_Num.f90):
// EulerConstruct, the change of basis (global to local) of rotations about x,
// y, z by theta (intrinsic z-y-x), M = R(z) R(y) R(x); EulerExtract its inverse.
#include <Eigen/Core>
#include <cmath>
#include <limits>

namespace yamsc::aero {

inline bool euler_nearly_zero(double x) {
    return std::abs(x) <= 50.0 * std::numeric_limits<double>::epsilon();
}

/// NWTC's EulerConstruct: the change of basis (global to local) of the rotations
/// about x, y, z by theta (intrinsic z-y-x), M = R(z) R(y) R(x).
/// A zero angle (the BEM's annulus and root frames have two or one) takes no
/// trigonometry: cos(+-0) = 1 and sin(+-0) = +-0 exactly.
inline Eigen::Matrix3d euler_construct(const Eigen::Vector3d& t) {
    const auto cos_of = [](double a) { return a == 0 ? 1.0 : std::cos(a); };
    const auto sin_of = [](double a) { return a == 0 ? a : std::sin(a); };
    const double cx = cos_of(t[0]), sx = sin_of(t[0]), cy = cos_of(t[1]), sy = sin_of(t[1]),
                 cz = cos_of(t[2]), sz = sin_of(t[2]);
    Eigen::Matrix3d m;
    m << cy * cz, cx * sz + sx * sy * cz, sx * sz - cx * sy * cz, //
        -cy * sz, cx * cz - sx * sy * sz, sx * cz + cx * sy * sz, //
        sy, -sx * cy, cx * cy;
    return m;
}

/// NWTC's EulerExtract, the inverse of euler_construct. Without `about_x` the
/// angle about x is left 0 (its arc tangent is the third of the extraction's;
/// the BEM's node frames need only the angles about y and z).
inline Eigen::Vector3d euler_extract(const Eigen::Matrix3d& m, bool about_x = true) {
    double cy = std::hypot(m(0, 0), m(1, 0));
    Eigen::Vector3d t;
    if (euler_nearly_zero(cy)) {
        t[1] = std::atan2(m(2, 0), cy);
        t[2] = 0;
        t[0] = std::atan2(m(1, 2), m(1, 1));
        return t;
    }
    t[2] = std::atan2(-m(1, 0), m(0, 0));
    double cz = std::cos(t[2]), sz = std::sin(t[2]);
    cy = euler_nearly_zero(cz) ? std::copysign(cy, -m(1, 0) / sz) : std::copysign(cy, m(0, 0) / cz);
    t[1] = std::atan2(m(2, 0), cy);
    if (!about_x) {
        t[0] = 0;
        return t;
    }
    const double cx = sz * m(0, 1) + cz * m(1, 1), sx = sz * m(0, 2) + cz * m(1, 2);
    t[0] = std::atan2(sx, cx);
    return t;
}

} // namespace yamsc::aero
