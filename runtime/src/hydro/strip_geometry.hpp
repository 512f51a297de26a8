#pragma once
// The geometry of the strip-theory block (strip_theory.hpp): the submerged part
// of a member (a frustum cut by the still-water plane) and the members' nodes,
// strips and joints in body axes.
#include <yamsc/hydro/strip_theory.hpp>

#include <Eigen/Dense>

#include <vector>

namespace yamsc::runtime::hydro::strip {

/// Volume below z = 0 of the frustum from a (radius ra) to b (radius rb) and its
/// first moment (volume times centroid), in the axes of a and b: the whole frustum
/// when both centres are below, the part below the plane when the axis crosses it
/// (exact while the plane cuts the side wall only), nothing when both are above.
struct Submerged {
    double volume = 0;
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
};
Submerged submerged_frustum(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double ra,
                            double rb);

/// A member in body axes, divided into equal elements (HydroDyn's CEILING(L / MDivSize)).
struct Member {
    Eigen::Vector3d end1, end2, axis; // body axes; axis: unit, end1 to end2
    double length = 0, element = 0;   // L and the element length dl
    double radius1 = 0, radius2 = 0;
    int elements = 1;
    StripCoefficients c1, c2;
    bool potential_flow = false;
    /// Node n (0..elements) in body axes, its radius and coefficients.
    Eigen::Vector3d node(int n) const { return end1 + (element * n) * axis; }
    double radius(int n) const;
    StripCoefficients coefficients(int n) const;
    double taper() const { return (radius2 - radius1) / length; } // dR/dl
};

/// The part of the member's axis around node n that the node's strip stands for,
/// given which nodes are in the water (z at or below the still-water level): its
/// length and the offset of its centre from the node along the axis (HydroDyn's
/// deltal and h_c without wave stretching). z: the nodes' heights.
struct StripSpan {
    double length = 0, offset = 0;
};
StripSpan strip_span(const std::vector<double>& z, int n, double element);

/// Member ends that meet at one point (within 1e-6 m): HydroDyn's joints.
struct Joint {
    Eigen::Vector3d position;  // body axes
    Eigen::Vector3d area_drag; // sum of outward normal * end area, every member
    Eigen::Vector3d area;      // the same, members not modelled by potential flow
    Eigen::Vector3d volume;    // sum of outward normal * 2/3 pi R^3, the same members
    JointCoefficients c;
};

std::vector<Member> body_members(const StripSetup& setup);
std::vector<Joint> body_joints(const StripSetup& setup, const std::vector<Member>& members);

} // namespace yamsc::runtime::hydro::strip
