#include "yamsc/aero/rigid_rotor.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace yamsc::aero {

namespace {

constexpr double pi = 3.14159265358979323846;
using Vec = Eigen::Vector3d;

// The blade's coned frame (ElastoDyn's i1, i2, i3: unpitched) and pitched frame
// (j1, j2, j3) for blade k at the operating point.
struct BladeFrames {
    Vec i1, i2, i3, j1, j2, j3;
};

struct RotorFrames {
    Vec hub;    // apex of rotation
    Vec c1;     // shaft axis, downwind (ElastoDyn's c1 = e1 = g1)
    Vec e2, e3; // rotating, e3 along blade 1 without precone
};

RotorFrames rotor_frames(const RotorGeometry& g, double azimuth) {
    const Vec d1(std::cos(g.yaw), std::sin(g.yaw), 0.0), d2(0, 0, 1);
    const Vec d3(std::sin(g.yaw), -std::cos(g.yaw), 0.0);
    const double ct = std::cos(g.shaft_tilt), st = std::sin(g.shaft_tilt);
    const Vec c1 = ct * d1 + st * d2, c2 = -st * d1 + ct * d2, c3 = d3;
    // ElastoDyn's internal rotor angle is the output azimuth less 90 deg.
    const double q = azimuth - pi / 2;
    RotorFrames f;
    f.c1 = c1;
    f.e2 = std::cos(q) * c2 + std::sin(q) * c3;
    f.e3 = -std::sin(q) * c2 + std::cos(q) * c3;
    f.hub = Vec(0, 0, g.tower_height) + g.twr2shft * d2 + g.overhang * c1;
    return f;
}

BladeFrames blade_frames(const RotorFrames& r, const RotorGeometry& g, int k, int blades,
                         double pitch) {
    const double b = 2.0 * pi * k / blades;
    const Vec g2 = std::cos(b) * r.e2 + std::sin(b) * r.e3;
    const Vec g3 = -std::sin(b) * r.e2 + std::cos(b) * r.e3;
    const double cc = std::cos(g.precone), sc = std::sin(g.precone);
    BladeFrames f;
    f.i1 = cc * r.c1 - sc * g3;
    f.i2 = g2;
    f.i3 = sc * r.c1 + cc * g3;
    const double cp = std::cos(pitch), sp = std::sin(pitch);
    f.j1 = cp * f.i1 - sp * f.i2;
    f.j2 = sp * f.i1 + cp * f.i2;
    f.j3 = f.i3;
    return f;
}

} // namespace

RigidRotor::RigidRotor(const RotorInput& input, const RotorGeometry& geometry)
    : input_(input), geometry_(geometry), rotor_(input, geometry.hub_radius) {
    motion_.blades.resize(input.blades.size());
    for (std::size_t k = 0; k < input.blades.size(); ++k) {
        const std::size_t n = input.blades[k].size();
        motion_.blades[k].position.resize(n);
        motion_.blades[k].velocity.resize(n);
        motion_.blades[k].axes.resize(n);
    }
}

const RotorResult& RigidRotor::evaluate(const OperatingPoint& op, bool warm_start) {
    const int nb = static_cast<int>(input_.blades.size());
    const RotorFrames rf = rotor_frames(geometry_, op.azimuth);
    const Vec omega = op.rotor_speed * rf.c1;
    motion_.hub_position = rf.hub;
    motion_.hub_axes.col(0) = rf.c1;
    motion_.hub_axes.col(1) = rf.e2;
    motion_.hub_axes.col(2) = rf.e3;
    motion_.hub_angular_velocity = omega;
    for (int k = 0; k < nb; ++k) {
        const BladeFrames bf = blade_frames(rf, geometry_, k, nb, op.pitch);
        RotorMotion::Blade& b = motion_.blades[static_cast<std::size_t>(k)];
        b.root_axes.col(0) = bf.j1;
        b.root_axes.col(1) = bf.j2;
        b.root_axes.col(2) = bf.j3;
        const Vec root = rf.hub + geometry_.hub_radius * bf.i3;
        const auto& nodes = input_.blades[static_cast<std::size_t>(k)];
        for (std::size_t j = 0; j < nodes.size(); ++j) {
            const BladeNode& n = nodes[j];
            b.position[j] = root + n.curve_ac * bf.j1 + n.sweep_ac * bf.j2 + n.span * bf.j3;
            b.velocity[j] = omega.cross(b.position[j] - rf.hub);
            b.axes[j] = b.root_axes * BemRotor::node_axes_in_root(n);
        }
        b.wind.clear();
        if (op.wind_field)
            for (const Vec& p : b.position)
                b.wind.push_back(op.wind_field->velocity(0.0, p, op.wind_speed));
    }
    const Vec wind =
        op.wind_speed * Vec(std::cos(op.wind_direction), -std::sin(op.wind_direction), 0.0);
    return rotor_.evaluate(motion_, wind, warm_start);
}

} // namespace yamsc::aero
