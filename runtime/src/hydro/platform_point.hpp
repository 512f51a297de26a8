#pragma once
// The platform reference point (HydroDyn's WAMIT mesh node) on a body's mesh:
// where it is and how it moves, and loads at it back to the body's origin.
#include <yamsc/body_mesh.hpp>
#include <yamsc/hydro/additional_loads.hpp>

#include <Eigen/Dense>

namespace yamsc::runtime::hydro::detail {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

inline Matrix6 to_eigen(const Mat6& m) {
    return Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(m.data());
}

/// OpenFAST's EulerExtract: the angles with R = Rx(x) Ry(y) Rz(z), R the body's
/// axes in ground components.
Eigen::Vector3d euler_extract(const Eigen::Matrix3d& R);

struct PointState {
    BodyFrame frame;
    Eigen::Vector3d arm_body;   // the point from the body origin, body axes
    Eigen::Vector3d arm_ground; // the same in ground axes
    PlatformMotion motion;      // HydroDyn's q, q' of the point
};

/// The point `reference` (global, at rest) of the body whose mesh outputs are r.
PointState point_state(const double* r, const Vec3& reference, const Vec3& origin_at_rest);

/// A force and moment (ground axes, moment about the point) as the body's loads:
/// force and moment at its origin, body axes.
void to_body_loads(const PointState& s, const Vector6& ground, double* loads);

/// J with [a_point; alpha] (ground) = J [a_origin; alpha] (body), without rate terms.
Matrix6 point_jacobian(const PointState& s);

} // namespace yamsc::runtime::hydro::detail
