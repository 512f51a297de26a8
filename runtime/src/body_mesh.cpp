#include "yamsc/body_mesh.hpp"

#include <cmath>

namespace yamsc::runtime {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

std::size_t modes_of(const BodyFrame& f, const BodyPoint& p) {
    return std::min(f.q.size(), p.phi.size());
}

/// ∂p/∂q_k of the node's position p in body axes: Φ_k + Σ_j ½ (Φ¹_kj + Φ¹_jk) q_j
/// (the derivation's node motion; no storage, as blocks call this per node and step).
Vector3d dp_dq(const BodyFrame& f, const BodyPoint& pt, std::size_t k) {
    Vector3d dp = pt.phi[k];
    if (pt.phi1.empty()) return dp;
    const std::size_t n = modes_of(f, pt);
    for (std::size_t j = 0; j < n; ++j)
        dp += 0.5 * (pt.phi1[k * n + j] + pt.phi1[j * n + k]) * f.q[j];
    return dp;
}

/// The node's displacement p - origin = Σ_k (Φ_k + ½ Σ_j Φ¹_kj q_j) q_k.
Vector3d displacement(const BodyFrame& f, const BodyPoint& pt) {
    const std::size_t n = modes_of(f, pt);
    Vector3d p = Vector3d::Zero();
    for (std::size_t k = 0; k < n; ++k) {
        Vector3d shape = pt.phi[k];
        if (!pt.phi1.empty())
            for (std::size_t j = 0; j < n; ++j)
                shape += 0.25 * (pt.phi1[k * n + j] + pt.phi1[j * n + k]) * f.q[j];
        p += shape * f.q[k];
    }
    return p;
}

Vector3d elastic_angles(const BodyFrame& f, const BodyPoint& pt) {
    Vector3d th = Vector3d::Zero();
    for (std::size_t k = 0; k < modes_of(f, pt); ++k) th += pt.psi[k] * f.q[k];
    return th;
}

/// Body-axes angular velocity of the node per unit rate of each angle, for the
/// rotations about x, then y, then z: the columns e_x, Rx e_y, Rx Ry e_z
/// (written out; (1 - cx) + cx is Rx's first diagonal term as a rotation about
/// an axis forms it).
Matrix3d angle_rates(const Vector3d& th) {
    const double cx = std::cos(th.x()), sx = std::sin(th.x());
    const double cy = std::cos(th.y()), sy = std::sin(th.y());
    Matrix3d W;
    W.col(0) = Vector3d::UnitX();
    W.col(1) = Vector3d(0, cx, sx);
    W.col(2) = Vector3d(((1 - cx) + cx) * sy, -sx * cy, cx * cy);
    return W;
}

/// ElastoDyn's small rotation (SmllRotTrans): the rotation of the unit quaternion
/// (w, th/2), about th by about |th|, with no second-order twist.
Matrix3d small_rotation(const Vector3d& th) {
    const Vector3d h = 0.5 * th;
    const double w = std::sqrt(std::max(0.0, 1 - h.squaredNorm()));
    return Eigen::Quaterniond(w, h.x(), h.y(), h.z()).toRotationMatrix();
}

} // namespace

void read_body_frame(const double* v, std::size_t modes, BodyFrame& f) {
    f.r = Vector3d(v[0], v[1], v[2]);
    f.v = Vector3d(v[3], v[4], v[5]);
    f.w = Vector3d(v[6], v[7], v[8]);
    for (int axis = 0; axis < 3; ++axis)
        f.R.col(axis) = Vector3d(v[9 + 3 * axis], v[10 + 3 * axis], v[11 + 3 * axis]);
    constexpr std::size_t frame = 18;
    f.q.assign(v + frame, v + frame + modes);
    f.qd.assign(v + frame + modes, v + frame + 2 * modes);
}

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

Vector3d point_position(const BodyFrame& f, const BodyPoint& pt) {
    return f.r + f.R * (pt.origin + displacement(f, pt));
}

PointMotion point_motion(const BodyFrame& f, const BodyPoint& pt) {
    const Vector3d th = elastic_angles(f, pt);
    const Matrix3d W = angle_rates(th);
    // dp_dq's and displacement's sums in one pass (the same operations in the
    // same order): each symmetric pair Φ¹_kj + Φ¹_jk is formed once.
    const std::size_t n = modes_of(f, pt);
    Vector3d pd = Vector3d::Zero(), thd = Vector3d::Zero(), p = Vector3d::Zero();
    for (std::size_t k = 0; k < n; ++k) {
        Vector3d dp = pt.phi[k], shape = pt.phi[k];
        if (!pt.phi1.empty())
            for (std::size_t j = 0; j < n; ++j) {
                const Vector3d pair = pt.phi1[k * n + j] + pt.phi1[j * n + k];
                dp += 0.5 * pair * f.q[j];
                shape += 0.25 * pair * f.q[j];
            }
        pd += dp * f.qd[k];
        thd += pt.psi[k] * f.qd[k];
        p += shape * f.q[k];
    }
    const Vector3d rho = f.R * (pt.origin + p);
    PointMotion m;
    m.r = f.r + rho;
    m.v = f.v + f.w.cross(rho) + f.R * pd;
    m.w = f.w + f.R * (W * thd);
    m.R = f.R * small_rotation(th) * pt.orientation;
    return m;
}

PointSite point_site(const BodyFrame& f, const BodyPoint& pt) {
    PointSite s;
    s.body = pt.origin + displacement(f, pt);
    s.ground = f.r + f.R * s.body;
    return s;
}

void add_point_load(const BodyFrame& f, const BodyPoint& pt, const Vector3d& force,
                    const Vector3d& moment, BodyLoad& load) {
    add_point_load(f, pt, point_site(f, pt), force, moment, load);
}

void add_point_load(const BodyFrame& f, const BodyPoint& pt, const PointSite& site,
                    const Vector3d& force, const Vector3d& moment, BodyLoad& load) {
    const std::size_t n = modes_of(f, pt);
    const Matrix3d W = angle_rates(elastic_angles(f, pt));
    const Vector3d& rho = site.body; // body axes
    const Vector3d fb = f.R.transpose() * force, mb = f.R.transpose() * moment;
    // The body frame's share: the wrench moved to the origin.
    load.force += fb;
    load.moment += rho.cross(fb) + mb;
    // Each mode's: the point's partial velocity and partial angular velocity.
    if (load.modal.size() < n) load.modal.resize(n, 0.0);
    for (std::size_t k = 0; k < n; ++k)
        load.modal[k] += dp_dq(f, pt, k).dot(fb) + (W * pt.psi[k]).dot(mb);
}

} // namespace yamsc::runtime
