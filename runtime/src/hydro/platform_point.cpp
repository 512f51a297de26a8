#include "platform_point.hpp"

#include <cmath>

namespace yamsc::runtime::hydro::detail {

Eigen::Vector3d euler_extract(const Eigen::Matrix3d& R) {
    // R = Rx Ry Rz: R(0,2) = sin y, R(1,2) = -sin x cos y, R(2,2) = cos x cos y,
    // R(0,1) = -cos y sin z, R(0,0) = cos y cos z.
    const double y = std::asin(std::max(-1.0, std::min(1.0, R(0, 2))));
    return {std::atan2(-R(1, 2), R(2, 2)), y, std::atan2(-R(0, 1), R(0, 0))};
}

PointState point_state(const double* r, const Vec3& reference, const Vec3& origin_at_rest) {
    PointState s;
    read_body_frame(r, 0, s.frame);
    const Eigen::Vector3d ref(reference[0], reference[1], reference[2]);
    s.arm_body = ref - Eigen::Vector3d(origin_at_rest[0], origin_at_rest[1], origin_at_rest[2]);
    s.arm_ground = s.frame.R * s.arm_body;
    const Eigen::Vector3d position = s.frame.r + s.arm_ground;
    const Eigen::Vector3d velocity = s.frame.v + s.frame.w.cross(s.arm_ground);
    const Eigen::Vector3d angles = euler_extract(s.frame.R);
    for (int i = 0; i < 3; ++i) {
        s.motion.q[static_cast<std::size_t>(i)] = position[i] - ref[i];
        s.motion.q[static_cast<std::size_t>(3 + i)] = angles[i];
        s.motion.qd[static_cast<std::size_t>(i)] = velocity[i];
        s.motion.qd[static_cast<std::size_t>(3 + i)] = s.frame.w[i];
        for (int c = 0; c < 3; ++c)
            s.motion.R[static_cast<std::size_t>(3 * i + c)] = s.frame.R(i, c);
    }
    return s;
}

void to_body_loads(const PointState& s, const Vector6& ground, double* loads) {
    const Eigen::Vector3d f = s.frame.R.transpose() * ground.head<3>();
    const Eigen::Vector3d m = s.frame.R.transpose() * ground.tail<3>() + s.arm_body.cross(f);
    for (int i = 0; i < 3; ++i) {
        loads[i] += f[i];
        loads[3 + i] += m[i];
    }
}

Matrix6 point_jacobian(const PointState& s) {
    Eigen::Matrix3d arm;
    arm << 0, -s.arm_body.z(), s.arm_body.y(), s.arm_body.z(), 0, -s.arm_body.x(), -s.arm_body.y(),
        s.arm_body.x(), 0;
    Matrix6 J = Matrix6::Zero();
    J.topLeftCorner<3, 3>() = s.frame.R;
    J.topRightCorner<3, 3>() = -s.frame.R * arm;
    J.bottomRightCorner<3, 3>() = s.frame.R;
    return J;
}

} // namespace yamsc::runtime::hydro::detail
