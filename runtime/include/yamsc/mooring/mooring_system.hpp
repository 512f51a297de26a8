#pragma once
// Quasi-static mooring lines between fixed anchors and fairleads on one body
// (a floating platform): the loads they put on the body at a pose, and their
// exact derivatives with respect to the pose (the mooring's stiffness in `lin`).
#include <yamsc/mooring/catenary.hpp>

#include <array>
#include <vector>

namespace yamsc::runtime::mooring {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>; // row-major

struct Line {
    LineProperties properties;
    Vec3 anchor{};   // in the inertial frame, z up [m]
    Vec3 fairlead{}; // in the body's frame, from its reference point [m]
};

/// Where the body is: its reference point and the rotation from its axes to
/// the inertial ones (a point p of the body is at position + rotation p).
struct Pose {
    Vec3 position{};
    Mat3 rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};
};

struct LineState {
    CatenarySolution solution;
    Vec3 fairlead{};         // the fairlead in the inertial frame
    Vec3 force_on_body{};    // what the line does to the body at its fairlead
    Mat3 force_derivative{}; // d(force_on_body)/d(fairlead), inertial frame
    double tension() const;  // the fairlead's effective tension, sqrt(H^2 + V^2)
};

struct MooringLoads {
    Vec3 force{};  // on the body, in the inertial frame
    Vec3 moment{}; // about the body's reference point, in the inertial frame
    // d(force, moment)/d(position, rotation), 6 x 6 row-major: a rotation is a
    // small one about the inertial axes, R -> (I + [theta]x) R. Minus it is the
    // restoring matrix of the lines (C_mooring).
    std::array<double, 36> derivative{};
    std::vector<LineState> lines;
};

/// The lines' loads on the body at `pose`. `previous`, when it holds as many
/// lines, starts each line's solve at its last solution.
MooringLoads mooring_loads(const std::vector<Line>& lines, const Pose& pose,
                           const MooringLoads* previous = nullptr);

} // namespace yamsc::runtime::mooring
