#include "strip_geometry.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace yamsc::runtime::hydro::strip {
namespace {

constexpr double pi = 3.14159265358979323846;

Eigen::Vector3d vec(const Vec3& v) {
    return {v[0], v[1], v[2]};
}

// Below this taper (dR/dl) the submerged part is computed as a cylinder: the
// difference of two cones would lose about eps / taper of its digits.
constexpr double cylinder_taper = 1e-7;
// HydroDyn refuses an element nearly parallel to the free surface alike.
constexpr double least_cosine = 1e-4;

// The part of the frustum from p (below the plane, radius rp) towards q, cut by
// z = 0, relative to p: the volume between p's end cap and the plane.
Submerged cut_frustum(const Eigen::Vector3d& p, const Eigen::Vector3d& q, double rp, double rq) {
    const double length = (q - p).norm();
    const Eigen::Vector3d k = (q - p) / length;
    const double cos_g = k.z();
    const double t = (rq - rp) / length;
    if (cos_g < least_cosine || std::abs(t) * std::sqrt(1 - cos_g * cos_g) >= cos_g)
        throw std::invalid_argument("strip theory: a member crosses the still-water level "
                                    "nearly parallel to it");
    const double h0 = -p.z() / cos_g; // along the axis to the plane
    const double tan2 = (1 - cos_g * cos_g) / (cos_g * cos_g);
    // tan(gamma) times the unit vector in the section plane towards the surface normal.
    const Eigen::Vector3d w = (Eigen::Vector3d::UnitZ() - cos_g * k) / cos_g;
    Submerged s;
    if (std::abs(t) < cylinder_taper) {
        const double r = rp + 0.5 * t * h0;
        const double r2 = r * r;
        s.volume = pi * r2 * h0;
        // The plane's slope moves the volume towards the low side of the cut.
        s.moment = (pi * r2 * (4 * h0 * h0 + r2 * tan2) / 8) * k - (pi * r2 * r2 / 4) * w;
    } else {
        // Two cones from the apex: to the plane (an ellipse of area pi rh^2 /
        // (C^1.5 cos g)) and to p's cap; a cone's centroid is 3/4 of the way from
        // its apex to its base's centroid.
        const double sigma = t > 0 ? 1.0 : -1.0;
        const double tau = std::abs(t);
        const Eigen::Vector3d kappa = sigma * k; // the way the cone opens
        const Eigen::Vector3d apex = -(rp / t) * k;
        const double rh = rp + t * h0;
        if (!(rh > 0))
            throw std::invalid_argument("strip theory: a member tapers to a point below the "
                                        "still-water level");
        const double c = 1 - tau * tau * tan2;
        const double height = rh / tau;
        const double v_plane = pi * rh * rh * height / (3 * c * std::sqrt(c));
        const Eigen::Vector3d ellipse = apex + height * (1 + tau * tau * tan2 / c) * kappa -
                                        (sigma * tau * tau * height / c) * w;
        const Eigen::Vector3d c_plane = apex + 0.75 * (ellipse - apex);
        const double h_cap = rp / tau;
        const double v_cap = pi * rp * rp * h_cap / 3;
        const Eigen::Vector3d c_cap = apex + 0.75 * h_cap * kappa;
        s.volume = sigma * (v_plane - v_cap);
        s.moment = sigma * (v_plane * c_plane - v_cap * c_cap);
    }
    s.moment += s.volume * p;
    return s;
}

} // namespace

Submerged submerged_frustum(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double ra,
                            double rb) {
    const bool a_in = a.z() <= 0, b_in = b.z() <= 0;
    if (!a_in && !b_in) return {};
    if (a_in && b_in) {
        const double length = (b - a).norm();
        const double sum = ra * ra + ra * rb + rb * rb;
        Submerged s;
        s.volume = pi * length * sum / 3;
        const double along = length * (ra * ra + 2 * ra * rb + 3 * rb * rb) / (4 * sum);
        s.moment = s.volume * (a + (along / length) * (b - a));
        return s;
    }
    return a_in ? cut_frustum(a, b, ra, rb) : cut_frustum(b, a, rb, ra);
}

double Member::radius(int n) const {
    const double s = static_cast<double>(n) / elements;
    return (1 - s) * radius1 + s * radius2;
}

StripCoefficients Member::coefficients(int n) const {
    const double s = static_cast<double>(n) / elements;
    auto mix = [s](double a, double b) { return (1 - s) * a + s * b; };
    return {mix(c1.cd, c2.cd),       mix(c1.ca, c2.ca),       mix(c1.cp, c2.cp),
            mix(c1.ax_cd, c2.ax_cd), mix(c1.ax_ca, c2.ax_ca), mix(c1.ax_cp, c2.ax_cp)};
}

StripSpan strip_span(const std::vector<double>& z, int n, double element) {
    const int last = static_cast<int>(z.size()) - 1;
    const auto at = static_cast<std::size_t>(n);
    if (z[at] > 0) return {};
    // The share of the element from n to its neighbour that is in the water.
    auto side = [&](int neighbour) {
        const double zn = z[static_cast<std::size_t>(neighbour)];
        if (zn <= 0) return 0.5 * element;
        return -z[at] / (zn - z[at]) * element;
    };
    const double left = n > 0 ? side(n - 1) : 0.0;
    const double right = n < last ? side(n + 1) : 0.0;
    return {left + right, 0.5 * (right - left)};
}

std::vector<Member> body_members(const StripSetup& setup) {
    if (setup.members.empty()) throw std::invalid_argument("strip theory: no member");
    const Eigen::Vector3d origin = vec(setup.origin_at_rest);
    std::vector<Member> out;
    for (std::size_t i = 0; i < setup.members.size(); ++i) {
        const StripMember& m = setup.members[i];
        const std::string which = "strip theory: member " + std::to_string(i + 1);
        Member b;
        b.end1 = vec(m.end1) - origin;
        b.end2 = vec(m.end2) - origin;
        b.length = (b.end2 - b.end1).norm();
        if (!(b.length > 0)) throw std::invalid_argument(which + " has no length");
        if (!(m.diameter1 > 0) || !(m.diameter2 > 0))
            throw std::invalid_argument(which + ": its diameters must be positive");
        if (!(m.division_size > 0))
            throw std::invalid_argument(which + ": its division size must be positive");
        b.axis = (b.end2 - b.end1) / b.length;
        b.elements = std::max(1, static_cast<int>(std::ceil(b.length / m.division_size)));
        b.element = b.length / b.elements;
        b.radius1 = 0.5 * m.diameter1;
        b.radius2 = 0.5 * m.diameter2;
        b.c1 = m.c1;
        b.c2 = m.c2;
        b.potential_flow = m.potential_flow;
        out.push_back(b);
    }
    return out;
}

std::vector<Joint> body_joints(const StripSetup& setup, const std::vector<Member>& members) {
    std::vector<Joint> joints;
    auto add = [&](const Eigen::Vector3d& at, const Eigen::Vector3d& outward, double r,
                   bool potential_flow, const StripCoefficients& axial, int drag_model) {
        Joint* j = nullptr;
        for (Joint& o : joints)
            if ((o.position - at).norm() < 1e-6) j = &o;
        if (!j) {
            Joint fresh;
            fresh.position = at;
            fresh.area_drag = fresh.area = fresh.volume = Eigen::Vector3d::Zero();
            fresh.c = {axial.ax_cd, axial.ax_ca, axial.ax_cp, drag_model};
            joints.push_back(fresh);
            j = &joints.back();
        }
        j->area_drag += pi * r * r * outward;
        if (potential_flow) return;
        j->area += pi * r * r * outward;
        j->volume += (2 * pi / 3) * r * r * r * outward;
    };
    for (std::size_t i = 0; i < members.size(); ++i) {
        const Member& m = members[i];
        const StripMember& s = setup.members[i];
        add(m.end1, -m.axis, m.radius1, m.potential_flow, s.joint1_axial, s.joint1_drag_model);
        add(m.end2, m.axis, m.radius2, m.potential_flow, s.joint2_axial, s.joint2_drag_model);
    }
    return joints;
}

} // namespace yamsc::runtime::hydro::strip
