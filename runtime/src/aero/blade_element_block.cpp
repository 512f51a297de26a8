#include "yamsc/aero/blade_element_block.hpp"

#include "yamsc/aero/bem_rotor.hpp"

#include "element_dynamics.hpp"
#include "euler.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace yamsc::aero {

namespace {

constexpr double pi = 3.14159265358979323846;
using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr int frame_outputs = 18; // model/mesh_channels.hpp: r, v, w, x, y, z axes
constexpr int frame_inputs = 6;   // force, moment

const char* const rotor_outputs[] = {"RtSpeed",  "RtTSR",    "RtVAvgxh", "RtSkew",  "RtFldFxh",
                                     "RtFldMxh", "RtFldPwr", "RtFldCp",  "RtFldCt", "RtFldCq"};
const char* const node_outputs[] = {"Alpha", "Phi", "Vrel", "AxInd", "TnInd",
                                    "Cl",    "Cd",  "Fx",   "Fy"};

/// The segment of the sorted `x` holding `v` and the weight of its upper end
/// (clamped to the ends).
std::pair<std::size_t, double> bracket(const std::vector<double>& x, double v) {
    if (v <= x.front()) return {0, 0.0};
    if (v >= x.back()) return {x.size() - 2, 1.0};
    const std::size_t i =
        static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), v) - x.begin()) - 1;
    return {i, (v - x[i]) / (x[i + 1] - x[i])};
}

/// The structural nodes of a blade as ElastoDyn loads them: those strictly
/// inside the span, each carrying the load per length over its element (from
/// the midpoints to its neighbours; the end elements reach the root and the
/// tip). With ElastoDyn's discretization (`elements = N`, nodes at the element
/// centres) each length is the element's, span / N.
struct LoadedNode {
    std::size_t point;
    double span, length;
};

std::vector<LoadedNode> loaded_nodes(const std::vector<runtime::BodyPoint>& points) {
    std::vector<double> z;
    for (const auto& p : points) z.push_back(p.origin.z());
    const double tip = *std::max_element(z.begin(), z.end());
    std::vector<LoadedNode> nodes;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (z[i] > 1e-9 * tip && z[i] < tip * (1 - 1e-9)) nodes.push_back({i, z[i], 0.0});
    std::sort(nodes.begin(), nodes.end(),
              [](const LoadedNode& a, const LoadedNode& b) { return a.span < b.span; });
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const double lo = i == 0 ? 0.0 : 0.5 * (nodes[i - 1].span + nodes[i].span);
        const double hi = i + 1 == nodes.size() ? tip : 0.5 * (nodes[i].span + nodes[i + 1].span);
        nodes[i].length = hi - lo;
    }
    return nodes;
}

/// A blade: its AeroDyn nodes as points of its structure, and the structural
/// nodes its loads go to.
struct BladeMap {
    std::vector<runtime::BodyPoint> aero_points; // at the AeroDyn spans (no offsets)
    std::vector<Vector3d> offsets;               // BlCrvAC, BlSwpAC in the pitched root axes
    std::vector<Matrix3d> node_in_root;          // curve and twist
    std::vector<double> aero_span;
    std::vector<LoadedNode> loaded;
    std::size_t modes = 0;
};

BladeMap map_blade(const std::vector<BladeNode>& nodes, const BladeElementChannels::Blade& ch) {
    if (ch.points.size() < 2)
        throw std::invalid_argument("blade elements: a blade needs a flexible body with nodes "
                                    "along its span (a beam)");
    BladeMap m;
    std::vector<runtime::BodyPoint> sorted = ch.points;
    std::sort(sorted.begin(), sorted.end(),
              [](const runtime::BodyPoint& a, const runtime::BodyPoint& b) {
                  return a.origin.z() < b.origin.z();
              });
    std::vector<double> z;
    for (const auto& p : sorted) z.push_back(p.origin.z());
    for (const BladeNode& n : nodes) {
        const auto [i, s] = bracket(z, n.span);
        runtime::BodyPoint p = runtime::blend(sorted[i], sorted[i + 1], s);
        p.origin = Vector3d(0, 0, n.span);
        m.aero_points.push_back(std::move(p));
        m.offsets.emplace_back(n.curve_ac, n.sweep_ac, 0.0);
        m.node_in_root.push_back(BemRotor::node_axes_in_root(n));
        m.aero_span.push_back(n.span);
    }
    m.loaded = loaded_nodes(ch.points);
    m.modes = ch.points.front().phi.size();
    return m;
}

/// Active rotation by -pitch about z: the pitch of ElastoDyn (towards feather).
Matrix3d pitched(double pitch) {
    Matrix3d r;
    r << std::cos(pitch), std::sin(pitch), 0, -std::sin(pitch), std::cos(pitch), 0, 0, 0, 1;
    return r;
}

void read_frame(const double* v, runtime::BodyFrame& f, std::size_t modes) {
    f.r = Vector3d(v[0], v[1], v[2]);
    f.v = Vector3d(v[3], v[4], v[5]);
    f.w = Vector3d(v[6], v[7], v[8]);
    for (int axis = 0; axis < 3; ++axis)
        f.R.col(axis) = Vector3d(v[9 + 3 * axis], v[10 + 3 * axis], v[11 + 3 * axis]);
    f.q.assign(v + frame_outputs, v + frame_outputs + modes);
    f.qd.assign(v + frame_outputs + modes, v + frame_outputs + 2 * modes);
}

class BladeElementBlock final : public runtime::LoadBlock {
public:
    explicit BladeElementBlock(BladeElementSetup s) : s_(std::move(s)) {
        const BladeElementChannels& c = s_.channels;
        if (c.blades.empty() || c.blades.size() > s_.rotor.blades.size())
            throw std::invalid_argument(
                "blade elements: the model has " + std::to_string(c.blades.size()) +
                " blade(s), the AeroDyn input " + std::to_string(s_.rotor.blades.size()));
        s_.rotor.blades.resize(c.blades.size());
        ports_.outputs_read = c.hub_outputs;
        for (std::size_t k = 0; k < c.blades.size(); ++k) {
            maps_.push_back(map_blade(s_.rotor.blades[k], c.blades[k]));
            ports_.outputs_read.insert(ports_.outputs_read.end(), c.blades[k].outputs.begin(),
                                       c.blades[k].outputs.end());
            ports_.loads.insert(ports_.loads.end(), c.blades[k].loads.begin(),
                                c.blades[k].loads.end());
        }
        ports_.inputs_read = {c.wind, c.pitch};
        frames_.resize(c.blades.size());
        body_loads_.resize(c.blades.size());
        motion_.blades.resize(c.blades.size());
        node_omega_.resize(c.blades.size());
        dynamics_.emplace(s_.rotor);
        for (std::size_t k = 0; k < c.blades.size(); ++k) {
            const std::size_t n = s_.rotor.blades[k].size();
            node_omega_[k].resize(n);
            motion_.blades[k].position.resize(n);
            motion_.blades[k].velocity.resize(n);
            motion_.blades[k].axes.resize(n);
        }
        for (const char* o : rotor_outputs) names_.push_back(s_.output_prefix + o);
        for (std::size_t k = 0; k < c.blades.size(); ++k)
            for (std::size_t j = 0; j < s_.output_nodes.size(); ++j)
                for (const char* o : node_outputs)
                    names_.push_back(s_.output_prefix + "B" + std::to_string(k + 1) + "N" +
                                     std::to_string(j + 1) + o);
        for (int node : s_.output_nodes)
            if (node < 1 || node > static_cast<int>(s_.rotor.blades.front().size()))
                throw std::invalid_argument("blade elements: output node " + std::to_string(node) +
                                            " is not a node of the blade");
    }

    const runtime::BlockPorts& ports() const override { return ports_; }
    std::vector<std::string> output_names() const override { return names_; }

    void evaluate(double, const double*, const double* r, double* loads, double*,
                  double* out) const override {
        const RotorResult* res = &solve(r, wind(r));
        if (dynamics_->active()) res = &apply_dynamics();
        write_loads(*res, loads);
        write_outputs(*res, out);
    }

    bool has_discrete_states() const override { return dynamics_->active(); }

    void update_discrete_states(double t, const double*, const double* r, double t_next,
                                const double*, const double* r_next) const override {
        update_dynamics(t_next - t, r, r_next);
    }

private:
    double wind(const double* r) const { return r[ports_.outputs_read.size()]; }

    /// The rotor solved quasi-steadily at the motion read in r and the wind
    /// `wind_speed` (the steady BEM, AeroDyn's element solves and integrals).
    const RotorResult& solve(const double* r, double wind_speed) const {
        const std::size_t hub_n = s_.channels.hub_outputs.size();
        const double* blade_values = r + hub_n;
        const double* inputs = r + ports_.outputs_read.size();
        const bool pitch_given = s_.channels.pitch >= 0;
        runtime::BodyFrame hub;
        read_frame(r, hub, 0);
        motion_.hub_position = hub.r;
        motion_.hub_axes = hub.R;
        motion_.hub_angular_velocity = hub.w;
        for (std::size_t k = 0; k < maps_.size(); ++k) {
            const BladeMap& m = maps_[k];
            runtime::BodyFrame& f = frames_[k];
            read_frame(blade_values, f, m.modes);
            blade_values += frame_outputs + 2 * m.modes;
            // The pitch input replaces the pitch the blade's frame has about its
            // z axis relative to the hub (AeroDyn reads it so, StorePitchAndAzimuth).
            const double frame_pitch =
                pitch_given ? -euler_extract(f.R.transpose() * hub.R)[2] : 0.0;
            const Matrix3d rp = pitched(pitch_given ? inputs[1] - frame_pitch : 0.0);
            RotorMotion::Blade& b = motion_.blades[k];
            b.root_axes = f.R * rp;
            for (std::size_t j = 0; j < m.aero_points.size(); ++j) {
                const runtime::PointMotion pm = runtime::point_motion(f, m.aero_points[j]);
                const Matrix3d axes = pm.R * rp;
                const Vector3d offset = axes * m.offsets[j];
                b.position[j] = pm.r + offset;
                b.velocity[j] = pm.v + pm.w.cross(offset);
                b.axes[j] = axes * m.node_in_root[j];
                node_omega_[k][j] = pm.w;
            }
        }
        if (!rotor_) {
            // The hub radius: blade 1's root from the apex (ElastoDyn's HubRad).
            const double hub_radius = (frames_[0].r - hub.r).norm();
            rotor_.emplace(s_.rotor, hub_radius);
        }
        return rotor_->evaluate(motion_, Vector3d(wind_speed, 0, 0), true);
    }

    /// The rotor just solved, with DBEMT's filtered inductions and UA's
    /// coefficients of the block's discrete states.
    const RotorResult& apply_dynamics() const {
        dynamics_->apply(*rotor_, motion_, node_omega_);
        return rotor_->result();
    }

    /// AeroDyn's BEMT_UpdateStates from the values read at t (r) and t + dt (r_next).
    void update_dynamics(double dt, const double* r, const double* r_next) const {
        const double wind_t = wind(r), wind_next = wind(r_next);
        dynamics_->update(dt, wind_t != wind_next, [&](bool at_next, bool with_wind_next) {
            solve(at_next ? r_next : r, at_next || with_wind_next ? wind_next : wind_t);
            return ElementDynamics::Solved{&*rotor_, &motion_, &node_omega_};
        });
    }

    /// Each blade's loads per length, interpolated at its structural nodes and
    /// set there over their elements.
    void write_loads(const RotorResult& res, double* loads) const {
        for (std::size_t k = 0; k < maps_.size(); ++k) {
            const BladeMap& m = maps_[k];
            const auto& nodes = res.blades[k];
            runtime::BodyLoad& load = body_loads_[k];
            load.force.setZero();
            load.moment.setZero();
            load.modal.assign(m.modes, 0.0);
            for (const LoadedNode& n : m.loaded) {
                const auto [j, s] = bracket(m.aero_span, n.span);
                auto per_length = [&](const NodeResult& a) {
                    return std::pair<Vector3d, Vector3d>{a.bem.fx * a.x - a.bem.fy * a.y,
                                                         a.bem.mz * a.z};
                };
                const auto [f0, m0] = per_length(nodes[j]);
                const auto [f1, m1] = per_length(nodes[j + 1]);
                runtime::add_point_load(frames_[k], s_.channels.blades[k].points[n.point],
                                        ((1 - s) * f0 + s * f1) * n.length,
                                        ((1 - s) * m0 + s * m1) * n.length, load);
            }
            for (int c = 0; c < 3; ++c) {
                loads[c] = load.force[c];
                loads[3 + c] = load.moment[c];
            }
            for (std::size_t i = 0; i < m.modes; ++i) loads[frame_inputs + i] = load.modal[i];
            loads += frame_inputs + m.modes;
        }
    }

    void write_outputs(const RotorResult& res, double* out) const {
        const double deg = 180 / pi;
        const double omega = motion_.hub_angular_velocity.dot(motion_.hub_axes.col(0));
        const double rotor[] = {omega * 30 / pi, res.tsr,   res.v_avg_xh, res.skew * deg, res.fxh,
                                res.mxh,         res.power, res.cp,       res.ct,         res.cq};
        out = std::copy(std::begin(rotor), std::end(rotor), out);
        for (std::size_t k = 0; k < maps_.size(); ++k)
            for (int node : s_.output_nodes) {
                const NodeResult& n = res.blades[k][static_cast<std::size_t>(node - 1)];
                const double v[] = {n.bem.alpha * deg, n.bem.phi * deg, n.bem.vrel,
                                    n.bem.a,           n.bem.ap,        n.bem.cl,
                                    n.bem.cd,          n.bem.fx,        n.bem.fy};
                out = std::copy(std::begin(v), std::end(v), out);
            }
    }

    BladeElementSetup s_;
    runtime::BlockPorts ports_;
    std::vector<BladeMap> maps_;
    std::vector<std::string> names_;
    // Scratch and AeroDyn's constraint state (the last inflow angles): a block
    // belongs to one simulation, run by one thread.
    mutable std::optional<BemRotor> rotor_;
    mutable RotorMotion motion_;
    mutable std::vector<runtime::BodyFrame> frames_;
    mutable std::vector<runtime::BodyLoad> body_loads_;
    mutable std::vector<std::vector<Vector3d>> node_omega_; // per AeroDyn node (ground axes)
    // AeroDyn's discrete states (DBEMT, UA) and their updates.
    mutable std::optional<ElementDynamics> dynamics_;
};

} // namespace

std::shared_ptr<const runtime::LoadBlock> blade_element_block(BladeElementSetup setup) {
    return std::make_shared<BladeElementBlock>(std::move(setup));
}

} // namespace yamsc::aero
