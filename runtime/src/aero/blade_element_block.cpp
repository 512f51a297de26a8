#include "yamsc/aero/blade_element_block.hpp"

#include "yamsc/aero/bem_rotor.hpp"

#include "block_tower.hpp"
#include "element_dynamics.hpp"
#include "euler.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
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

/// The structural nodes of a blade that take loads: those strictly inside its
/// span (ElastoDyn's element centres with `elements = N`; it ignores loads at
/// the root and tip nodes of its mesh), in span order.
struct LoadedNode {
    std::size_t point;
    double span;
};

std::vector<LoadedNode> loaded_nodes(const std::vector<runtime::BodyPoint>& points) {
    double tip = 0;
    for (const auto& p : points) tip = std::max(tip, p.origin.z());
    std::vector<LoadedNode> nodes;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double z = points[i].origin.z();
        if (z > 1e-9 * tip && z < tip * (1 - 1e-9)) nodes.push_back({i, z});
    }
    std::sort(nodes.begin(), nodes.end(),
              [](const LoadedNode& a, const LoadedNode& b) { return a.span < b.span; });
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
    bool rigid = false;               // a rigid blade body: its loads lumped at the AeroDyn nodes
    std::vector<std::size_t> nearest; // per AeroDyn node: the structural node its load goes to
    std::size_t modes = 0;
};

/// A rigid blade's points: the AeroDyn nodes themselves, along its z axis.
std::vector<runtime::BodyPoint> rigid_points(const std::vector<BladeNode>& nodes) {
    std::vector<runtime::BodyPoint> points(nodes.size());
    for (std::size_t j = 0; j < nodes.size(); ++j) points[j].origin = Vector3d(0, 0, nodes[j].span);
    return points;
}

BladeMap map_blade(const std::vector<BladeNode>& nodes, BladeElementChannels::Blade& ch) {
    BladeMap m;
    if (ch.points.size() < 2) { // a rigid blade body
        ch.points = rigid_points(nodes);
        m.rigid = true;
    }
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
    for (const BladeNode& n : nodes) {
        std::size_t best = m.loaded.front().point;
        for (const LoadedNode& l : m.loaded)
            if (std::abs(l.span - n.span) < std::abs(ch.points[best].origin.z() - n.span))
                best = l.point;
        m.nearest.push_back(best);
    }
    m.modes = ch.points.front().phi.size();
    return m;
}

/// Active rotation by -pitch about z: the pitch of ElastoDyn (towards feather).
Matrix3d pitched(double pitch) {
    Matrix3d r;
    r << std::cos(pitch), std::sin(pitch), 0, -std::sin(pitch), std::cos(pitch), 0, 0, 0, 1;
    return r;
}

class BladeElementBlock final : public runtime::LoadBlock {
public:
    explicit BladeElementBlock(BladeElementSetup s) : s_(std::move(s)) {
        BladeElementChannels& c = s_.channels;
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
        add_tower();
        ports_.inputs_read = {c.wind, c.pitch};
        frames_.resize(c.blades.size());
        body_loads_.resize(c.blades.size());
        lumped_force_.resize(c.blades.size());
        lumped_moment_.resize(c.blades.size());
        motion_.blades.resize(c.blades.size());
        node_omega_.resize(c.blades.size());
        dynamics_.emplace(s_.rotor);
        for (std::size_t k = 0; k < c.blades.size(); ++k) {
            const std::size_t n = s_.rotor.blades[k].size();
            node_omega_[k].resize(n);
            motion_.blades[k].position.resize(n);
            motion_.blades[k].velocity.resize(n);
            motion_.blades[k].axes.resize(n);
            motion_.blades[k].wind.resize(n);
        }
        for (const char* o : rotor_outputs) names_.push_back(s_.output_prefix + o);
        for (std::size_t k = 0; k < c.blades.size(); ++k)
            for (std::size_t j = 0; j < s_.rotor.output_nodes.size(); ++j)
                for (const char* o : node_outputs)
                    names_.push_back(s_.output_prefix + "B" + std::to_string(k + 1) + "N" +
                                     std::to_string(j + 1) + o);
        for (int node : s_.rotor.output_nodes)
            if (node < 1 || node > static_cast<int>(s_.rotor.blades.front().size()))
                throw std::invalid_argument("blade elements: output node " + std::to_string(node) +
                                            " is not a node of the blade");
    }

    const runtime::BlockPorts& ports() const override { return ports_; }
    std::vector<std::string> output_names() const override { return names_; }

    void evaluate(double t, const double*, const double* r, double* loads, double*,
                  double* out) const override {
        // The time, values read, states and wake of the last evaluation again (the
        // controller's measurement and the integrator's first stage at a step's
        // start): its loads and outputs stand.
        const std::size_t nr = ports_.outputs_read.size() + ports_.inputs_read.size();
        const std::size_t nl = ports_.loads.size();
        const double tag[] = {t, static_cast<double>(dynamics_->generation()),
                              rotor_ && rotor_->wake_frozen() ? 1.0 : 0.0};
        if (evaluated_key_.size() == 3 + nr &&
            std::memcmp(evaluated_key_.data(), tag, sizeof tag) == 0 &&
            std::memcmp(evaluated_key_.data() + 3, r, nr * sizeof(double)) == 0) {
            std::copy(evaluated_.begin(), evaluated_.begin() + nl, loads);
            std::copy(evaluated_.begin() + nl, evaluated_.end(), out);
            return;
        }
        evaluated_key_.clear();
        const RotorResult* res = &solve(r, t, wind(r));
        if (dynamics_->active()) res = &apply_dynamics();
        write_loads(*res, loads);
        tower_->write_loads(loads + ports_.loads.size() - tower_->loads().size());
        write_outputs(*res, out);
        evaluated_key_.assign(std::begin(tag), std::end(tag));
        evaluated_key_.insert(evaluated_key_.end(), r, r + nr);
        evaluated_.assign(loads, loads + nl);
        evaluated_.insert(evaluated_.end(), out, out + names_.size());
    }

    bool has_discrete_states() const override { return dynamics_->active(); }

    void update_discrete_states(double t, const double*, const double* r, double t_next,
                                const double*, const double* r_next) const override {
        update_dynamics(t, t_next, r, r_next);
    }

    void reset_discrete_states() const override { dynamics_->reset(); }

    void derivatives(double t, const double* z, const double* r,
                     runtime::BlockJacobian& j) const override {
        if (s_.frozen_wake)
            frozen_wake_derivatives(t, z, r, j);
        else
            runtime::central_differences(*this, t, z, r, j, s_.difference_step);
    }

private:
    double wind(const double* r) const { return r[ports_.outputs_read.size()]; }

    /// The rotor solved quasi-steadily at the motion read in r and the wind
    /// of time `wind_time` with V_wind `wind_speed` (the steady BEM, AeroDyn's
    /// element solves and integrals); with inputs_only its element inputs alone.
    const RotorResult& solve(const double* r, double wind_time, double wind_speed,
                             bool inputs_only = false) const {
        const Vector3d uniform(wind_speed, 0, 0);
        auto rotor = [&]() -> const RotorResult& {
            return inputs_only
                       ? rotor_->element_inputs(motion_, uniform)
                       : rotor_->evaluate(motion_, uniform, true, !dynamics_->replaces_loads());
        };
        // The values and wind of the last call again (a step's measurement, first
        // stage and update read the same): its motion stands (every input of it is
        // in the key; the wind field's time too, unless the field is steady).
        const std::size_t nr = ports_.outputs_read.size() + ports_.inputs_read.size();
        const double key_time = s_.wind_field && !s_.wind_field->steady() ? wind_time : 0.0;
        const bool same_motion = rotor_ && motion_key_.size() == nr + 2 &&
                                 std::memcmp(r, motion_key_.data(), nr * sizeof(double)) == 0;
        if (same_motion && motion_key_[nr] == wind_speed && motion_key_[nr + 1] == key_time)
            return rotor();
        motion_key_.clear();
        // The tower's values follow the hub's and the blades'.
        const double* blade_values = r + s_.channels.hub_outputs.size();
        if (same_motion) // only the wind differs (DBEMT's input at a step's start): the
                         // nodes' motion stands
            for (const BladeMap& m : maps_) blade_values += frame_outputs + 2 * m.modes;
        else
            blade_values = read_motion(r, blade_values);
        if (!rotor_) {
            // The hub radius: blade 1's root from the apex (ElastoDyn's HubRad).
            const double hub_radius = (frames_[0].r - motion_.hub_position).norm();
            rotor_.emplace(s_.rotor, hub_radius);
            rotor_->use_warm_bracket();
        }
        // InflowWind's wind at each node's deflected position, then the tower's
        // disturbance on top (AeroDyn's InflowOnBlade, DisturbedInflow).
        const FreeWind free{s_.wind_field.get(), wind_time, wind_speed};
        for (RotorMotion::Blade& b : motion_.blades)
            free.at(b.position.data(), b.position.size(), b.wind.data());
        tower_->read(blade_values, free);
        tower_->disturb(motion_);
        motion_key_.assign(r, r + nr);
        motion_key_.push_back(wind_speed);
        motion_key_.push_back(key_time);
        return rotor();
    }

    /// The hub's and the blades' frames and the AeroDyn nodes' motion from the
    /// values read (blade_values: the blades' first); returns where the tower's
    /// values start.
    const double* read_motion(const double* r, const double* blade_values) const {
        const double* inputs = r + ports_.outputs_read.size();
        const bool pitch_given = s_.channels.pitch >= 0;
        runtime::BodyFrame hub;
        runtime::read_body_frame(r, 0, hub);
        motion_.hub_position = hub.r;
        motion_.hub_axes = hub.R;
        motion_.hub_angular_velocity = hub.w;
        for (std::size_t k = 0; k < maps_.size(); ++k) {
            const BladeMap& m = maps_[k];
            runtime::BodyFrame& f = frames_[k];
            runtime::read_body_frame(blade_values, m.modes, f);
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
        return blade_values;
    }

    /// The rotor just solved, with DBEMT's filtered inductions and UA's
    /// coefficients of the block's discrete states.
    const RotorResult& apply_dynamics() const {
        dynamics_->apply(*rotor_, motion_, node_omega_);
        return rotor_->result();
    }

    /// AeroDyn's BEMT_UpdateStates from the values read at t (r) and t + dt (r_next).
    void update_dynamics(double t, double t_next, const double* r, const double* r_next) const {
        const double wind_t = wind(r), wind_next = wind(r_next);
        const bool field_changes = s_.wind_field && !s_.wind_field->steady();
        dynamics_->update(t_next - t, wind_t != wind_next || field_changes,
                          [&](bool at_next, bool with_wind_next, bool inputs_only) {
                              const bool next = at_next || with_wind_next;
                              solve(at_next ? r_next : r, next ? t_next : t,
                                    next ? wind_next : wind_t, inputs_only);
                              return ElementDynamics::Solved{&*rotor_, &motion_, &node_omega_};
                          });
    }

    /// The inductions of the point (r, z) held while the loads are differenced;
    /// the block's states, if any, are the point's too (z is not moved by the
    /// read values' columns).
    void frozen_wake_derivatives(double t, const double* z, const double* r,
                                 runtime::BlockJacobian& j) const {
        std::vector<double> loads(ports_.loads.size()), rates(state_names().size()),
            out(names_.size());
        evaluate(t, z, r, loads.data(), rates.data(), out.data());
        rotor_->freeze_wake();
        try {
            runtime::central_differences(*this, t, z, r, j, s_.difference_step);
        } catch (...) {
            rotor_->release_wake();
            throw;
        }
        rotor_->release_wake();
    }

    /// The tower role's channels after the blades' (tower_influence.hpp).
    void add_tower() {
        const TowerChannels& t = s_.channels.tower;
        tower_.emplace(s_.rotor, t);
        if (!tower_->used()) return;
        ports_.outputs_read.insert(ports_.outputs_read.end(), t.outputs.begin(), t.outputs.end());
        ports_.loads.insert(ports_.loads.end(), tower_->loads().begin(), tower_->loads().end());
    }

    /// Each blade's loads into its mesh inputs.
    void write_loads(const RotorResult& res, double* loads) const {
        for (std::size_t k = 0; k < maps_.size(); ++k) {
            const BladeMap& m = maps_[k];
            const auto& nodes = res.blades[k];
            runtime::BodyLoad& load = body_loads_[k];
            load.force.setZero();
            load.moment.setZero();
            load.modal.assign(m.modes, 0.0);
            lumped_loads(k, nodes, load);
            for (int c = 0; c < 3; ++c) {
                loads[c] = load.force[c];
                loads[3 + c] = load.moment[c];
            }
            for (std::size_t i = 0; i < m.modes; ++i) loads[frame_inputs + i] = load.modal[i];
            loads += frame_inputs + m.modes;
        }
    }

    /// AeroDyn's loads as OpenFAST hands them to ElastoDyn: the loads per length
    /// linear between the AeroDyn nodes, lumped to them (line2 to point), each
    /// lumped load moved to the nearest structural node with the moment of the
    /// offset (point to point), there set on the blade through the node's partial
    /// velocities. A rigid blade takes them at the AeroDyn nodes themselves.
    void lumped_loads(std::size_t k, const std::vector<NodeResult>& nodes,
                      runtime::BodyLoad& load) const {
        const BladeMap& m = maps_[k];
        const auto& points = s_.channels.blades[k].points;
        // Each AeroDyn node's lumped load, then each at its structural node.
        std::vector<Vector3d>& force = lumped_force_[k];
        std::vector<Vector3d>& moment = lumped_moment_[k];
        force.assign(nodes.size(), Vector3d::Zero());
        moment.assign(nodes.size(), Vector3d::Zero());
        auto apply = [&](std::size_t j, const Vector3d& f, const Vector3d& mo) {
            force[j] += f;
            moment[j] += mo;
        };
        for (std::size_t j = 0; j + 1 < nodes.size(); ++j) {
            const NodeResult& p = nodes[j];
            const NodeResult& q = nodes[j + 1];
            const double len = (q.position - p.position).norm();
            const Vector3d fp = p.bem.fx * p.x - p.bem.fy * p.y,
                           fq = q.bem.fx * q.x - q.bem.fy * q.y;
            apply(j, len / 6.0 * (2.0 * fp + fq), len / 2.0 * p.bem.mz * p.z);
            apply(j + 1, len / 6.0 * (fp + 2.0 * fq), len / 2.0 * q.bem.mz * q.z);
        }
        if (m.rigid) {
            for (std::size_t j = 0; j < nodes.size(); ++j)
                runtime::add_point_load(frames_[k], points[j], force[j], moment[j], load);
            return;
        }
        // Gathered per structural node: the forces, and their moments about it.
        for (const LoadedNode& n : m.loaded) {
            const runtime::PointSite site = runtime::point_site(frames_[k], points[n.point]);
            const Vector3d& at = site.ground;
            Vector3d f = Vector3d::Zero(), mo = Vector3d::Zero();
            for (std::size_t j = 0; j < nodes.size(); ++j) {
                if (m.nearest[j] != n.point) continue;
                f += force[j];
                mo += moment[j] + (nodes[j].position - at).cross(force[j]);
            }
            runtime::add_point_load(frames_[k], points[n.point], site, f, mo, load);
        }
    }

    void write_outputs(const RotorResult& res, double* out) const {
        const double deg = 180 / pi;
        const double omega = motion_.hub_angular_velocity.dot(motion_.hub_axes.col(0));
        const double rotor[] = {omega * 30 / pi, res.tsr,   res.v_avg_xh, res.skew * deg, res.fxh,
                                res.mxh,         res.power, res.cp,       res.ct,         res.cq};
        out = std::copy(std::begin(rotor), std::end(rotor), out);
        for (std::size_t k = 0; k < maps_.size(); ++k)
            for (int node : s_.rotor.output_nodes) {
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
    mutable std::optional<BlockTower> tower_;
    mutable RotorMotion motion_;
    mutable std::vector<double> motion_key_; // the values read and the wind motion_ is of
    mutable std::vector<double> evaluated_key_, evaluated_; // the last evaluation's key, results
    mutable std::vector<runtime::BodyFrame> frames_;
    mutable std::vector<runtime::BodyLoad> body_loads_;
    mutable std::vector<std::vector<Vector3d>> lumped_force_, lumped_moment_; // per blade, node
    mutable std::vector<std::vector<Vector3d>> node_omega_; // per AeroDyn node (ground axes)
    // AeroDyn's discrete states (DBEMT, UA) and their updates.
    mutable std::optional<ElementDynamics> dynamics_;
};

} // namespace

std::shared_ptr<const runtime::LoadBlock> blade_element_block(BladeElementSetup setup) {
    return std::make_shared<BladeElementBlock>(std::move(setup));
}

} // namespace yamsc::aero
