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

// twist + pitch and the cant of a node whose frame is EulerConstruct(0, crv,
// -twist) on the pitched root frame, relative to the unpitched one (AeroDyn's
// Calculate_MeshOrientation_NoSweepPitchTwist): R = Rz(-twist) Ry(crv) Rz(-pitch)
// in NWTC's passive Euler convention, angles extracted as EulerExtract does away
// from its singularity.
struct NodeAngles {
    double theta, cant;
};
NodeAngles node_angles(double twist, double curve_angle, double pitch) {
    auto rz = [](double t) {
        Eigen::Matrix3d m;
        m << std::cos(t), std::sin(t), 0, -std::sin(t), std::cos(t), 0, 0, 0, 1;
        return m;
    };
    Eigen::Matrix3d ry;
    const double c = std::cos(curve_angle), s = std::sin(curve_angle);
    ry << c, 0, -s, 0, 1, 0, s, 0, c;
    const Eigen::Matrix3d m = rz(-twist) * ry * rz(-pitch);
    return {-std::atan2(-m(1, 0), m(0, 0)), std::asin(std::clamp(m(2, 0), -1.0, 1.0))};
}

} // namespace

RigidRotor::RigidRotor(const RotorInput& input, const RotorGeometry& geometry)
    : input_(input), geometry_(geometry), options_(bem_options(input)) {
    if (input.blades.empty()) throw std::invalid_argument("rigid rotor: no blade");
    for (const auto& blade : input.blades) {
        if (blade.size() < 2) throw std::invalid_argument("rigid rotor: a blade needs two nodes");
        // zLocal: the hub radius, then the distances between successive nodes.
        std::vector<double> z(blade.size());
        auto offset = [](const BladeNode& n) { return Vec(n.curve_ac, n.sweep_ac, n.span); };
        z[0] = geometry.hub_radius + offset(blade[0]).norm();
        for (std::size_t j = 1; j < blade.size(); ++j)
            z[j] = z[j - 1] + (offset(blade[j]) - offset(blade[j - 1])).norm();
        z_local_.push_back(std::move(z));
        for (const auto& n : blade)
            if (n.airfoil < 0 || n.airfoil >= static_cast<int>(input.airfoils.size()))
                throw std::invalid_argument("rigid rotor: a node's airfoil is not in the list");
    }
    result_.blades.resize(input.blades.size());
    for (std::size_t k = 0; k < input.blades.size(); ++k)
        result_.blades[k].resize(input.blades[k].size());
}

const RotorResult& RigidRotor::evaluate(const OperatingPoint& op, bool warm_start) {
    const int nb = static_cast<int>(input_.blades.size());
    const RotorFrames rf = rotor_frames(geometry_, op.azimuth);
    const Vec wind =
        op.wind_speed * Vec(std::cos(op.wind_direction), -std::sin(op.wind_direction), 0.0);
    const Vec omega = op.rotor_speed * rf.c1;

    // Node positions, frames and relative winds; the disk average.
    Vec v_sum = Vec::Zero();
    int count = 0;
    double r_max = 0;
    for (int k = 0; k < nb; ++k) {
        const BladeFrames bf = blade_frames(rf, geometry_, k, nb, op.pitch);
        const Vec root = rf.hub + geometry_.hub_radius * bf.i3;
        const auto& nodes = input_.blades[k];
        for (std::size_t j = 0; j < nodes.size(); ++j) {
            const BladeNode& n = nodes[j];
            NodeResult& out = result_.blades[k][j];
            out.position = root + n.curve_ac * bf.j1 + n.sweep_ac * bf.j2 + n.span * bf.j3;
            const Vec rel = out.position - rf.hub;
            const Vec v = wind - omega.cross(rel);
            v_sum += v;
            ++count;
            const NodeAngles ang = node_angles(n.twist, n.curve_angle, op.pitch);
            const double cc = std::cos(ang.cant), sc = std::sin(ang.cant);
            out.x = cc * bf.i1 - sc * bf.i3;
            out.y = bf.i2;
            out.z = sc * bf.i1 + cc * bf.i3;
            out.r_local = (rel - rf.c1 * rf.c1.dot(rel)).norm();
            r_max = std::max(r_max, out.r_local);
            out.vx = v.dot(out.x);
            out.vy = v.dot(out.y);
            ElementInput& in = out.input;
            in.vx = out.vx;
            in.vy = out.vy;
            in.r = out.r_local;
            in.z = z_local_[k][j];
            in.z_hub = geometry_.hub_radius;
            in.z_tip = z_local_[k].back();
            in.blades = nb;
            in.theta = ang.theta;
            in.chord = n.chord;
            in.airfoil = &input_.airfoils[n.airfoil];
            const bool warm = warm_start && solved_;
            in.guess_valid = warm && out.bem.valid;
            in.phi_guess = warm ? out.bem.phi_bem : 0.0;
        }
    }
    const Vec v_disk = v_sum / count;
    const double v_dot_x = v_disk.dot(rf.c1);
    const double v_norm = v_disk.norm();
    const double chi0 = v_norm == 0 ? 0.0 : std::acos(std::clamp(v_dot_x / v_norm, -1.0, 1.0));
    // The skew plane: y along the in-plane part of the wind (reversed), z normal
    // to the wind and the axis; psi_s measured from it.
    Vec y_disk = v_dot_x * rf.c1 - v_disk, z_disk;
    const double in_plane = y_disk.norm();
    if (in_plane <= 50.0 * std::numeric_limits<double>::epsilon()) {
        y_disk = rf.e2;
        z_disk = rf.e3;
    } else {
        y_disk /= in_plane;
        z_disk = v_disk.cross(rf.c1) / in_plane;
    }
    const double tsr = v_dot_x == 0 ? 0.0 : op.rotor_speed * r_max / v_dot_x;
    const double weight = induction_weight(tsr);

    Vec force = Vec::Zero(), moment = Vec::Zero();
    const double rho = input_.air_density;
    for (int k = 0; k < nb; ++k) {
        const BladeFrames bf = blade_frames(rf, geometry_, k, nb, op.pitch);
        const double psi = std::atan2(-bf.i3.dot(y_disk), bf.i3.dot(z_disk));
        auto& nodes = result_.blades[k];
        double r_tip = 0;
        for (const auto& n : nodes) r_tip = std::max(r_tip, n.r_local);
        for (auto& n : nodes) {
            n.input.chi0 = chi0;
            n.input.psi = psi;
            n.input.tip_ratio = n.r_local / r_tip;
            n.input.weight = weight;
            n.bem = solve_element(n.input, options_, rho);
        }
        // AeroDyn's line-to-point transfer: loads per length linear between the
        // nodes, lumped to the nodes, then summed about the hub.
        for (std::size_t j = 0; j + 1 < nodes.size(); ++j) {
            const NodeResult& p = nodes[j];
            const NodeResult& q = nodes[j + 1];
            const double len = (q.position - p.position).norm();
            const Vec fp = p.bem.fx * p.x - p.bem.fy * p.y, fq = q.bem.fx * q.x - q.bem.fy * q.y;
            const Vec mp = p.bem.mz * p.z, mq = q.bem.mz * q.z;
            const Vec lp = len / 6.0 * (2.0 * fp + fq), lq = len / 6.0 * (fp + 2.0 * fq);
            force += lp + lq;
            moment += (p.position - rf.hub).cross(lp) + (q.position - rf.hub).cross(lq) +
                      len / 6.0 * (3.0 * mp + 3.0 * mq);
        }
    }

    RotorResult& r = result_;
    r.fxh = force.dot(rf.c1);
    r.mxh = moment.dot(rf.c1);
    r.power = op.rotor_speed * r.mxh;
    r.r_max = r_max;
    r.tsr = tsr;
    r.skew = chi0;
    r.v_avg_xh = v_dot_x;
    if (std::abs(v_dot_x) < 0.04) {
        r.cp = r.ct = r.cq = 0;
    } else {
        const double q = 0.5 * rho * pi * r_max * r_max * v_dot_x * v_dot_x;
        r.cp = r.power / (q * v_dot_x);
        r.cq = r.mxh / (q * r_max);
        r.ct = r.fxh / q;
    }
    solved_ = true;
    return r;
}

} // namespace yamsc::aero
