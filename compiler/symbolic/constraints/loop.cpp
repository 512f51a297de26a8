// `constraint loop`: two frames of the tree joined by a point, revolute,
// prismatic or welded joint. Position rows: p_a - p_b in a's axes; orientation
// rows: products of a's and b's axes, zero when they are aligned.
#include "symbolic/constraints/registry.hpp"

namespace yamsc::symbolic {

namespace {

/// Axis i of a frame, ground axes.
Vec3 axis_of(const Mat3& R, int i) {
    const auto c = static_cast<std::size_t>(i);
    return {{R.m[0][c], R.m[1][c], R.m[2][c]}};
}

} // namespace

KindRows loop_rows(const model::Constraint& c, ConstraintContext& ctx) {
    const FrameMotion a = ctx.motion(c.a);
    const FrameMotion b = ctx.motion(c.b);
    KindRows rows;
    const Vec3 d = transpose_times(a.R, a.r - b.r);
    for (int i = 0; i < 3; ++i) {
        const bool along = c.joint == model::LoopJoint::prismatic && i == c.axis;
        if (c.components[static_cast<std::size_t>(i)] && !along)
            rows.holonomic.push_back(d[static_cast<std::size_t>(i)]);
    }
    if (c.joint == model::LoopJoint::revolute) {
        // b's axis in a's axes has no component across the axis.
        const Vec3 axis_b = transpose_times(a.R, axis_of(b.R, c.axis));
        for (int i = 0; i < 3; ++i)
            if (i != c.axis) rows.holonomic.push_back(axis_b[static_cast<std::size_t>(i)]);
    } else if (c.joint != model::LoopJoint::point) {
        // a_z.b_y, a_x.b_z, a_y.b_x: the small rotations of b in a about x, y, z.
        for (int i = 0; i < 3; ++i)
            rows.holonomic.push_back(dot(axis_of(a.R, (i + 2) % 3), axis_of(b.R, (i + 1) % 3)));
    }
    return rows;
}

} // namespace yamsc::symbolic
