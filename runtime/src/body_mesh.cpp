#include "yamsc/body_mesh.hpp"

#include <cmath>

namespace yamsc::runtime {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

std::size_t modes_of(const BodyFrame& f, const BodyPoint& p) {
    return std::min(f.q.size(), p.phi.size());
}

/// The node's displacement from its undeformed position, in body axes, and
/// ∂p/∂q_k = Φ_k + Σ_j ½ (Φ¹_kj + Φ¹_jk) q_j (the derivation's node motion).
struct Deflection {
    Vector3d p = Vector3d::Zero();
    std::vector<Vector3d> dp_dq;
};

Deflection deflection(const BodyFrame& f, const BodyPoint& pt) {
    const std::size_t n = modes_of(f, pt);
    Deflection d;
    d.dp_dq.assign(n, Vector3d::Zero());
    for (std::size_t k = 0; k < n; ++k) {
        Vector3d dp = pt.phi[k], half = Vector3d::Zero();
        if (!pt.phi1.empty())
            for (std::size_t j = 0; j < n; ++j) {
                const Vector3d c = 0.5 * (pt.phi1[k * n + j] + pt.phi1[j * n + k]);
                dp += c * f.q[j];
                half += c * f.q[j];
            }
        d.dp_dq[k] = dp;
        d.p += (pt.phi[k] + 0.5 * half) * f.q[k];
    }
    return d;
}

Vector3d elastic_angles(const BodyFrame& f, const BodyPoint& pt) {
    Vector3d th = Vector3d::Zero();
    for (std::size_t k = 0; k < modes_of(f, pt); ++k) th += pt.psi[k] * f.q[k];
    return th;
}

Matrix3d about(int axis, double angle) {
    return Eigen::AngleAxisd(angle, Vector3d::Unit(axis)).toRotationMatrix();
}

/// Body-axes angular velocity of the node per unit rate of each angle, for the
/// rotations about x, then y, then z: the columns e_x, Rx e_y, Rx Ry e_z.
Matrix3d angle_rates(const Vector3d& th) {
    const Matrix3d rx = about(0, th.x()), rxy = rx * about(1, th.y());
    Matrix3d W;
    W.col(0) = Vector3d::UnitX();
    W.col(1) = rx.col(1);
    W.col(2) = rxy.col(2);
    return W;
}

} // namespace

BodyPoint blend(const BodyPoint& a, const BodyPoint& b, double s) {
    auto mix = [s](const std::vector<Vector3d>& x, const std::vector<Vector3d>& y) {
        std::vector<Vector3d> out(x.size());
        for (std::size_t i = 0; i < x.size(); ++i) out[i] = (1 - s) * x[i] + s * y[i];
        return out;
    };
    BodyPoint p;
    p.origin = (1 - s) * a.origin + s * b.origin;
    p.phi = mix(a.phi, b.phi);
    p.psi = mix(a.psi, b.psi);
    if (!a.phi1.empty() && !b.phi1.empty()) p.phi1 = mix(a.phi1, b.phi1);
    p.orientation = s < 0.5 ? a.orientation : b.orientation;
    return p;
}

PointMotion point_motion(const BodyFrame& f, const BodyPoint& pt) {
    const Deflection d = deflection(f, pt);
    const Vector3d th = elastic_angles(f, pt);
    const Matrix3d W = angle_rates(th);
    Vector3d pd = Vector3d::Zero(), thd = Vector3d::Zero();
    for (std::size_t k = 0; k < d.dp_dq.size(); ++k) {
        pd += d.dp_dq[k] * f.qd[k];
        thd += pt.psi[k] * f.qd[k];
    }
    const Vector3d rho = f.R * (pt.origin + d.p);
    PointMotion m;
    m.r = f.r + rho;
    m.v = f.v + f.w.cross(rho) + f.R * pd;
    m.w = f.w + f.R * (W * thd);
    m.R = f.R * about(0, th.x()) * about(1, th.y()) * about(2, th.z()) * pt.orientation;
    return m;
}

void add_point_load(const BodyFrame& f, const BodyPoint& pt, const Vector3d& force,
                    const Vector3d& moment, BodyLoad& load) {
    const Deflection d = deflection(f, pt);
    const Matrix3d W = angle_rates(elastic_angles(f, pt));
    const Vector3d rho = pt.origin + d.p; // body axes
    const Vector3d fb = f.R.transpose() * force, mb = f.R.transpose() * moment;
    // The body frame's share: the wrench moved to the origin.
    load.force += fb;
    load.moment += rho.cross(fb) + mb;
    // Each mode's: the point's partial velocity and partial angular velocity.
    if (load.modal.size() < d.dp_dq.size()) load.modal.resize(d.dp_dq.size(), 0.0);
    for (std::size_t k = 0; k < d.dp_dq.size(); ++k)
        load.modal[k] += d.dp_dq[k].dot(fb) + (W * pt.psi[k]).dot(mb);
}

} // namespace yamsc::runtime
