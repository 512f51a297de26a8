#pragma once
// Points of a body that move with it, rigid or flexible, and loads at them: the
// runtime side of a load block's body roles (the compiler's mesh channels,
// compiler/model/mesh_channels.hpp). The generated model gives the motion of the
// body frame and of its modes; a point's motion follows from its shapes (a SID
// node's, or a blend of two nodes'), exactly as the derivation moves a joint on
// that node. A force and moment at the point become the body's loads through the
// point's partial velocities: the force and moment at the body origin (body
// axes) and the generalized force on each mode, Σ Jᵀ f with J the exact partial
// velocities of the point, so nothing is lost between the block and Kane's
// equations.
#include <Eigen/Dense>

#include <vector>

namespace yamsc::runtime {

/// The motion of a body frame and its modes, as its mesh channels give it.
struct BodyFrame {
    Eigen::Vector3d r, v, w;   // origin position, velocity, angular velocity (ground)
    Eigen::Matrix3d R;         // the body's axes, in ground components (columns)
    std::vector<double> q, qd; // its modes' coordinates and rates
};

/// The frame's motion from a body role's mesh outputs (model/mesh_channels.hpp:
/// r, v, w, the x, y, z axes, then `modes` coordinates and `modes` rates);
/// `f`'s storage is reused.
void read_body_frame(const double* outputs, std::size_t modes, BodyFrame& f);

/// A point of the body: undeformed position in body axes and, on a flexible
/// body, its shapes per mode (SID node terms: translation Φ with its
/// second-order part Φ¹ (axial shortening), rotation Ψ).
struct BodyPoint {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> phi, psi; // per mode k
    std::vector<Eigen::Vector3d> phi1;     // [k * nq + j]: Φ¹_·kj (empty: none)
    Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity(); // the node frame in body axes
};

/// `a` and `b` blended, (1 - s) a + s b: a point between two nodes.
BodyPoint blend(const BodyPoint& a, const BodyPoint& b, double s);

/// A point's motion: position, orientation, velocity and angular velocity, in
/// ground axes. The orientation (its axes in ground components) is the body's
/// axes turned by the elastic rotation θ = Ψ q, then the node's orientation. θ
/// turns as ElastoDyn's SmllRotTrans turns a blade node: about θ by about |θ|,
/// with no order of axes. A sequence (about x, then y) would add a twist θx θy / 2
/// that no mode describes; the air sees it as angle of attack (at the NREL 5-MW
/// tip, 0.04° once per revolution: 11 % of OoPDefl's azimuthal variation).
/// Position, velocity and angular velocity are the derivation's own, to rounding.
struct PointMotion {
    Eigen::Vector3d r, v, w;
    Eigen::Matrix3d R;
};

PointMotion point_motion(const BodyFrame& f, const BodyPoint& p);
/// Its position alone (point_motion's r).
Eigen::Vector3d point_position(const BodyFrame& f, const BodyPoint& p);

/// The loads a block sets on a body through its mesh channels: force and moment
/// at the body's origin in body axes, generalized force per mode.
struct BodyLoad {
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    std::vector<double> modal;
};

/// Adds force `f` and moment `m` (ground axes) acting at point `p` to `load`.
void add_point_load(const BodyFrame& frame, const BodyPoint& p, const Eigen::Vector3d& f,
                    const Eigen::Vector3d& m, BodyLoad& load);

/// Where a point is: from the body's origin in body axes, and in ground axes
/// (point_position's). A block that needs the position of the point it loads
/// gives it to add_point_load, which then does not compute it again.
struct PointSite {
    Eigen::Vector3d body, ground;
};
PointSite point_site(const BodyFrame& frame, const BodyPoint& p);
void add_point_load(const BodyFrame& frame, const BodyPoint& p, const PointSite& site,
                    const Eigen::Vector3d& f, const Eigen::Vector3d& m, BodyLoad& load);

} // namespace yamsc::runtime
