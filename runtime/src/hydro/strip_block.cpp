#include "strip_geometry.hpp"

#include <yamsc/body_mesh.hpp>

#include <cmath>
#include <stdexcept>

namespace yamsc::runtime::hydro {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr std::size_t frame_outputs = 18;

using Eigen::Matrix3d;
using Eigen::Vector3d;

Matrix3d cross_matrix(const Vector3d& v) {
    Matrix3d m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}

// A point of the body whose acceleration meets an added mass (a node's strip or a
// joint): force -mass * (its acceleration), in body axes.
struct MassPoint {
    Vector3d at;   // body axes
    Matrix3d mass; // body axes
};

class StripBlock final : public LoadBlock {
public:
    explicit StripBlock(StripSetup s)
        : setup_(std::move(s)), members_(strip::body_members(setup_)),
          joints_(strip::body_joints(setup_, members_)) {
        if (setup_.frame_outputs.size() != frame_outputs || setup_.loads.size() != 6)
            throw std::invalid_argument("strip theory: a body role has 18 frame outputs and "
                                        "6 frame inputs");
        water_ = setup_.waves ? setup_.waves->water() : setup_.water;
        ports_.outputs_read = setup_.frame_outputs;
        ports_.loads = setup_.loads;
        collect_added_mass();
        fix_strips();
        tabulate_fixed_points();
    }

    const BlockPorts& ports() const override { return ports_; }

    std::vector<std::string> output_names() const override {
        std::vector<std::string> names;
        for (const char* n : {"Fxi", "Fyi", "Fzi", "Mxi", "Myi", "Mzi", "Vsub"})
            names.push_back(setup_.output_prefix + n);
        return names;
    }

    void evaluate(double t, const double*, const double* r, double* loads, double*,
                  double* out) const override {
        BodyFrame frame;
        read_body_frame(r, 0, frame);
        Vector3d force = Vector3d::Zero(), moment = Vector3d::Zero(); // ground, about the origin
        auto apply = [&](const Vector3d& at, const Vector3d& f) {     // at: ground position
            force += f;
            moment += (at - frame.r).cross(f);
        };
        const double volume = hydrostatics(frame, apply);
        members_flow(t, frame, apply);
        joints_flow(t, frame, apply);
        Vector3d fb = frame.R.transpose() * force, mb = frame.R.transpose() * moment;
        velocity_products(frame, fb, mb);
        for (int i = 0; i < 3; ++i) {
            loads[i] = fb[i];
            loads[3 + i] = mb[i];
        }
        const Vector3d f = frame.R * fb, m = frame.R * mb;
        for (int i = 0; i < 3; ++i) {
            out[i] = f[i];
            out[3 + i] = m[i];
        }
        out[6] = volume;
    }

    bool has_added_mass() const override { return true; }
    void added_mass(double, const double*, const double*, double* A) const override {
        for (std::size_t i = 0; i < 36; ++i) A[i] = added_mass_[i];
    }

private:
    // Buoyancy of each member's submerged part: rho g V upwards at its centroid
    // (the pressure on the side wall and on the end caps together).
    template <class Apply> double hydrostatics(const BodyFrame& frame, Apply& apply) const {
        double total = 0;
        const double rho_g = water_.density * water_.gravity;
        for (const strip::Member& m : members_) {
            if (m.potential_flow) continue;
            const strip::Submerged s = strip::submerged_frustum(
                frame.r + frame.R * m.end1, frame.r + frame.R * m.end2, m.radius1, m.radius2);
            if (s.volume <= 0) continue;
            total += s.volume;
            apply(s.moment / s.volume, Vector3d(0, 0, rho_g * s.volume));
        }
        return total;
    }

    FlowAt flow_at(double t, const Vector3d& p) const {
        if (!setup_.waves || p.z() > 0) return {};
        return setup_.waves->flow(t, {p.x(), p.y(), p.z()});
    }

    // With the kinematics at the undisplaced positions (WaveDisp 0) the points the
    // waves are taken at never move: the field tabulates each once.
    void tabulate_fixed_points() {
        if (!setup_.waves || setup_.kinematics_displaced) return;
        BodyFrame rest;
        rest.r = Vector3d::Zero();
        rest.R = Matrix3d::Identity();
        for (const NodeStrip& strip : fixed_nodes_) {
            const Vector3d p = kinematics_point(rest, strip.body);
            fixed_strips_.push_back(
                strip.length > 0 && p.z() <= 0 ? setup_.waves->at({p.x(), p.y(), p.z()}) : nullptr);
        }
        for (const strip::Joint& j : joints_) {
            const Vector3d p = kinematics_point(rest, j.position);
            fixed_joints_.push_back(p.z() <= 0 ? setup_.waves->at({p.x(), p.y(), p.z()}) : nullptr);
        }
    }

    Vector3d kinematics_point(const BodyFrame& frame, const Vector3d& body) const {
        if (setup_.kinematics_displaced) return frame.r + frame.R * body;
        return Vector3d(setup_.origin_at_rest[0], setup_.origin_at_rest[1],
                        setup_.origin_at_rest[2]) +
               body;
    }

    static FlowAt tabulated(const std::shared_ptr<const PointWaves>& p, double t) {
        return p ? p->flow(t) : FlowAt{};
    }

    // A node's strip: its span (from the kinematics points' depths) and the
    // member's values at the node.
    struct NodeStrip {
        double length = 0;
        Vector3d body = Vector3d::Zero(); // the strip's point, body axes
        double radius = 0;
        StripCoefficients c;
    };

    static void member_strips(const strip::Member& m, const std::vector<double>& z,
                              std::vector<NodeStrip>& out) {
        const int nodes = m.elements + 1;
        out.resize(static_cast<std::size_t>(nodes));
        for (int n = 0; n < nodes; ++n) {
            const strip::StripSpan span = strip::strip_span(z, n, m.element);
            NodeStrip& s = out[static_cast<std::size_t>(n)];
            s.length = span.length;
            if (span.length <= 0) continue;
            s.body = m.node(n) + span.offset * m.axis;
            s.radius = m.radius(n);
            s.c = m.coefficients(n);
        }
    }

    // With the kinematics at the undisplaced positions (WaveDisp 0) the strips
    // never change: made once, all members' nodes in a row.
    void fix_strips() {
        if (setup_.kinematics_displaced) return;
        BodyFrame rest;
        rest.r = Vector3d::Zero();
        rest.R = Matrix3d::Identity();
        std::vector<double> z;
        std::vector<NodeStrip> one;
        for (const strip::Member& m : members_) {
            const int nodes = m.elements + 1;
            z.resize(static_cast<std::size_t>(nodes));
            for (int n = 0; n < nodes; ++n)
                z[static_cast<std::size_t>(n)] = kinematics_point(rest, m.node(n)).z();
            member_strips(m, z, one);
            fixed_nodes_.insert(fixed_nodes_.end(), one.begin(), one.end());
        }
    }

    // Drag and wave inertia on each node's strip (HydroDyn's distributed loads).
    template <class Apply> void members_flow(double t, const BodyFrame& frame, Apply& apply) const {
        const double rho = water_.density;
        std::vector<double> z;
        std::vector<NodeStrip> moving;
        std::size_t fixed = 0;
        for (const strip::Member& m : members_) {
            const int nodes = m.elements + 1;
            const std::size_t first = fixed;
            fixed += static_cast<std::size_t>(nodes);
            const NodeStrip* strips = fixed_nodes_.empty() ? nullptr : &fixed_nodes_[first];
            if (!strips) {
                z.resize(static_cast<std::size_t>(nodes));
                for (int n = 0; n < nodes; ++n)
                    z[static_cast<std::size_t>(n)] = kinematics_point(frame, m.node(n)).z();
                member_strips(m, z, moving);
                strips = moving.data();
            }
            const Vector3d k = frame.R * m.axis;
            const Matrix3d kkt = k * k.transpose();
            const Matrix3d ak = Matrix3d::Identity() - kkt;
            const double taper = m.taper();
            for (int n = 0; n < nodes; ++n) {
                const NodeStrip& strip = strips[n];
                if (strip.length <= 0) continue;
                const Vector3d& body = strip.body;
                const Vector3d at = frame.r + frame.R * body;
                const FlowAt water =
                    fixed_strips_.empty()
                        ? flow_at(t, kinematics_point(frame, body))
                        : tabulated(fixed_strips_[first + static_cast<std::size_t>(n)], t);
                const Vector3d structure = frame.v + frame.w.cross(at - frame.r);
                const Vector3d vrel =
                    Vector3d(water.velocity[0], water.velocity[1], water.velocity[2]) - structure;
                const double radius = strip.radius;
                const StripCoefficients& c = strip.c;
                const Vector3d normal = ak * vrel;
                Vector3d f = c.cd * rho * radius * normal.norm() * normal +
                             0.5 * c.ax_cd * rho * pi * radius * std::abs(taper) *
                                 std::abs(k.dot(vrel)) * (kkt * vrel);
                if (!m.potential_flow) {
                    const Vector3d a(water.acceleration[0], water.acceleration[1],
                                     water.acceleration[2]);
                    const double area = pi * radius * radius;
                    f += (c.ca + c.cp) * rho * area * (ak * a) +
                         2 * c.ax_ca * rho * area * std::abs(taper) * (kkt * a) +
                         2 * water.dynamic_pressure * c.ax_cp * pi * radius * taper * k;
                }
                apply(at, strip.length * f);
            }
        }
    }

    // The joints' axial loads: drag on the flow through the ends, and the wave's
    // dynamic pressure and acceleration on them.
    template <class Apply> void joints_flow(double t, const BodyFrame& frame, Apply& apply) const {
        const double rho = water_.density;
        for (std::size_t i = 0; i < joints_.size(); ++i) {
            const strip::Joint& j = joints_[i];
            const Vector3d kin = kinematics_point(frame, j.position);
            if (kin.z() > 0) continue;
            const Vector3d at = frame.r + frame.R * j.position;
            const FlowAt water =
                fixed_joints_.empty() ? flow_at(t, kin) : tabulated(fixed_joints_[i], t);
            Vector3d f = Vector3d::Zero();
            const double a2 = j.area_drag.squaredNorm();
            if (a2 > 0 && j.c.ax_cd != 0) {
                const Vector3d an = frame.R * j.area_drag;
                const Vector3d structure = frame.v + frame.w.cross(at - frame.r);
                const Vector3d vrel =
                    Vector3d(water.velocity[0], water.velocity[1], water.velocity[2]) - structure;
                const double vn = vrel.dot(an);
                const double drag = j.c.ax_cd * rho / (4 * a2);
                f += j.c.drag_model == 1 ? 2 * drag * std::abs(vn) * std::max(vn, 0.0) * an
                                         : drag * std::abs(vn) * vn * an;
            }
            const double vmag = j.volume.norm();
            if (vmag > 0) {
                const Vector3d v = frame.R * j.volume;
                const Vector3d a(water.acceleration[0], water.acceleration[1],
                                 water.acceleration[2]);
                f += (j.c.ax_ca * rho / vmag) * v * v.dot(a);
            }
            f -= j.c.ax_cp * water.dynamic_pressure * (frame.R * j.area);
            apply(at, f);
        }
    }

    // The added masses: on the strips of the nodes below the still-water level in
    // the undisplaced position (AMMod 0) and at the joints there; constant in body axes.
    void collect_added_mass() {
        const double rho = water_.density;
        const Vector3d origin(setup_.origin_at_rest[0], setup_.origin_at_rest[1],
                              setup_.origin_at_rest[2]);
        std::vector<double> z;
        for (const strip::Member& m : members_) {
            if (m.potential_flow) continue;
            const int nodes = m.elements + 1;
            z.resize(static_cast<std::size_t>(nodes));
            for (int n = 0; n < nodes; ++n)
                z[static_cast<std::size_t>(n)] = (origin + m.node(n)).z();
            const Matrix3d kkt = m.axis * m.axis.transpose();
            const Matrix3d ak = Matrix3d::Identity() - kkt;
            for (int n = 0; n < nodes; ++n) {
                const strip::StripSpan span = strip::strip_span(z, n, m.element);
                if (span.length <= 0) continue;
                const double radius = m.radius(n);
                const StripCoefficients c = m.coefficients(n);
                const double area = pi * radius * radius;
                const Matrix3d mass =
                    c.ca * rho * area * ak + 2 * c.ax_ca * rho * area * std::abs(m.taper()) * kkt;
                points_.push_back({m.node(n) + span.offset * m.axis, span.length * mass});
            }
        }
        for (const strip::Joint& j : joints_) {
            const double vmag = j.volume.norm();
            if ((origin + j.position).z() > 0 || vmag <= 0 || j.c.ax_ca == 0) continue;
            points_.push_back(
                {j.position, (j.c.ax_ca * rho / vmag) * j.volume * j.volume.transpose()});
        }
        Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
        for (const MassPoint& p : points_) {
            // a_point = a + alpha x p = a - [p x] alpha; its force acts at p.
            const Matrix3d px = cross_matrix(p.at);
            A.topLeftCorner<3, 3>() += p.mass;
            A.topRightCorner<3, 3>() -= p.mass * px;
            A.bottomLeftCorner<3, 3>() += px * p.mass;
            A.bottomRightCorner<3, 3>() -= px * p.mass * px;
        }
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) added_mass_[static_cast<std::size_t>(6 * i + j)] = A(i, j);
    }

    // The added masses' share of the points' accelerations that is not in
    // [a; alpha]: w x (w x p), body axes.
    void velocity_products(const BodyFrame& frame, Vector3d& fb, Vector3d& mb) const {
        const Vector3d w = frame.R.transpose() * frame.w;
        if (w.squaredNorm() == 0) return;
        for (const MassPoint& p : points_) {
            const Vector3d f = -(p.mass * w.cross(w.cross(p.at)));
            fb += f;
            mb += p.at.cross(f);
        }
    }

    StripSetup setup_;
    std::vector<strip::Member> members_;
    std::vector<strip::Joint> joints_;
    Water water_;
    BlockPorts ports_;
    std::vector<MassPoint> points_;
    // WaveDisp 0: the tabulated flow at each member node's strip (members in
    // order, null where dry) and at each joint.
    std::vector<std::shared_ptr<const PointWaves>> fixed_strips_, fixed_joints_;
    std::vector<NodeStrip> fixed_nodes_; // WaveDisp 0: every member's strips, made once
    std::array<double, 36> added_mass_{};
};

} // namespace

std::shared_ptr<const LoadBlock> strip_theory_block(StripSetup setup) {
    return std::make_shared<const StripBlock>(std::move(setup));
}

} // namespace yamsc::runtime::hydro
