#include "yamsc/aero/bem_rotor.hpp"

#include "euler.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace yamsc::aero {

namespace {

constexpr double pi = 3.14159265358979323846;
using Vec = Eigen::Vector3d;
using Mat = Eigen::Matrix3d;

bool nearly_zero(double x) {
    return std::abs(x) <= 50.0 * std::numeric_limits<double>::epsilon();
}

} // namespace

Mat BemRotor::node_axes_in_root(const BladeNode& node) {
    return euler_construct(Vec(0, node.curve_angle, -node.twist)).transpose();
}

BemRotor::BemRotor(const RotorInput& input, double hub_radius)
    : input_(input), hub_radius_(hub_radius), options_(bem_options(input)) {
    if (input.blades.empty()) throw std::invalid_argument("blade elements: no blade");
    for (const auto& blade : input.blades) {
        if (blade.size() < 2)
            throw std::invalid_argument("blade elements: a blade needs two nodes");
        for (const auto& n : blade)
            if (n.airfoil < 0 || n.airfoil >= static_cast<int>(input.airfoils.size()))
                throw std::invalid_argument("blade elements: a node's airfoil is not in the list");
        // zLocal: from the apex along the blade, the hub radius and then the
        // distances between successive nodes of the blade file.
        auto offset = [](const BladeNode& n) { return Vec(n.curve_ac, n.sweep_ac, n.span); };
        std::vector<double> z(blade.size());
        z[0] = hub_radius + offset(blade[0]).norm();
        for (std::size_t j = 1; j < blade.size(); ++j)
            z[j] = z[j - 1] + (offset(blade[j]) - offset(blade[j - 1])).norm();
        z_local_.push_back(std::move(z));
    }
    for (const Airfoil& a : input.airfoils) {
        polars_.emplace_back();
        if (!a.tables.empty() && !a.tables.front().alpha.empty())
            polars_.back().emplace(a.tables.front());
    }
    result_.blades.resize(input.blades.size());
    brackets_.resize(input.blades.size());
    for (std::size_t k = 0; k < input.blades.size(); ++k) {
        result_.blades[k].resize(input.blades[k].size());
        brackets_[k].resize(input.blades[k].size());
    }
}

const RotorResult& BemRotor::evaluate(const RotorMotion& motion, const Vec& wind, bool warm_start,
                                      bool loads) {
    const bool cached = warm_start && solved_ && frozen_.empty();
    if (cached) {
        const int kept = cache_.recall(motion, wind);
        if (kept != RotorCache::no_entry) {
            view_ = kept;
            if (loads && !result().loads) finish(motion);
            return result();
        }
    }
    if (!cached) cache_.clear();
    set_inputs(motion, wind, warm_start);
    for (std::size_t k = 0; k < result_.blades.size(); ++k)
        for (std::size_t j = 0; j < result_.blades[k].size(); ++j) {
            NodeResult& n = result_.blades[k][j];
            if (frozen_.empty())
                n.bem = warm_bracket_ ? solve_inductions(n.input, options_, brackets_[k][j])
                                      : solve_inductions(n.input, options_);
            else
                frozen_element(n, frozen_[k][j]);
        }
    result_.loads = !frozen_.empty(); // a frozen wake's nodes have their loads
    if (loads || result_.loads) finish(motion);
    if (cached) mirror_ = cache_.keep(result_);
    solved_ = true;
    return result_;
}

void BemRotor::materialize() {
    if (view_ == RotorCache::no_entry) return;
    if (mirror_ != view_) {
        result_ = cache_.entry(view_);
        mirror_ = view_;
    }
    view_ = RotorCache::no_entry;
}

RotorResult& BemRotor::mutable_result() {
    materialize();
    mirror_ = RotorCache::no_entry;
    return result_;
}

void BemRotor::finish(const RotorMotion& motion) {
    if (!mutable_result().loads)
        for (auto& nodes : result_.blades)
            for (NodeResult& n : nodes)
                finish_element(n.input, options_, input_.air_density, n.bem);
    integrate(motion);
}

const RotorResult& BemRotor::element_inputs(const RotorMotion& motion, const Vec& wind) {
    set_inputs(motion, wind, true);
    return result_;
}

void BemRotor::set_inputs(const RotorMotion& motion, const Vec& wind, bool warm_start) {
    mutable_result(); // the guesses are the current result's roots
    const std::size_t nb = std::min(motion.blades.size(), input_.blades.size());
    if (nb == 0) throw std::invalid_argument("blade elements: no blade in motion");
    const Vec x_disk = motion.hub_axes.col(0);
    const Mat hub = motion.hub_axes.transpose(); // AeroDyn's orientation: global to local
    const double omega = motion.hub_angular_velocity.dot(x_disk);

    // Frames and relative winds of every node; the disk average.
    Vec v_sum = Vec::Zero();
    int count = 0;
    double r_max = 0;
    for (std::size_t k = 0; k < nb; ++k) {
        const RotorMotion::Blade& b = motion.blades[k];
        Vec theta = euler_extract(b.root_axes.transpose() * hub.transpose());
        theta[2] = 0; // the root without its pitch
        const Mat no_pitch = euler_construct(theta) * hub;
        for (std::size_t j = 0; j < input_.blades[k].size(); ++j) {
            const BladeNode& n = input_.blades[k][j];
            NodeResult& out = result_.blades[k][j];
            const Vec angles = euler_extract(b.axes[j].transpose() * no_pitch.transpose(), false);
            const Mat annulus = euler_construct(Vec(0, angles[1], 0)) * no_pitch;
            out.position = b.position[j];
            out.x = annulus.row(0).transpose();
            out.y = annulus.row(1).transpose();
            out.z = annulus.row(2).transpose();
            const Vec rel = out.position - motion.hub_position;
            out.r_local = (rel - x_disk * x_disk.dot(rel)).norm();
            r_max = std::max(r_max, out.r_local);
            const Vec v = (b.wind.empty() ? wind : b.wind[j]) - b.velocity[j];
            v_sum += v;
            ++count;
            out.vx = v.dot(out.x);
            out.vy = v.dot(out.y);
            ElementInput& in = out.input;
            in.vx = out.vx;
            in.vy = out.vy;
            in.r = out.r_local;
            in.z = z_local_[k][j];
            in.z_hub = hub_radius_;
            in.z_tip = z_local_[k].back();
            in.blades = static_cast<int>(nb);
            in.theta = -angles[2];
            in.chord = n.chord;
            in.airfoil = &input_.airfoils[static_cast<std::size_t>(n.airfoil)];
            const auto& polar = polars_[static_cast<std::size_t>(n.airfoil)];
            in.polar = polar ? &*polar : nullptr;
            const bool warm = warm_start && solved_;
            in.guess_valid = warm && out.bem.valid;
            in.phi_guess = warm ? out.bem.phi_bem : 0.0;
        }
    }
    const Vec v_disk = v_sum / count;
    const double v_dot_x = v_disk.dot(x_disk);
    const double v_norm = v_disk.norm();
    double chi0 = v_norm == 0 ? 0.0 : std::acos(std::clamp(v_dot_x / v_norm, -1.0, 1.0));
    const Vec skew = v_disk.cross(x_disk);
    chi0 = std::copysign(chi0, std::abs(skew[1]) > std::abs(skew[2]) ? skew[1] : skew[2]);
    Vec y_disk = v_dot_x * x_disk - v_disk, z_disk;
    const double in_plane = y_disk.norm();
    if (nearly_zero(in_plane)) {
        y_disk = motion.hub_axes.col(1);
        z_disk = motion.hub_axes.col(2);
    } else {
        y_disk /= in_plane;
        z_disk = v_disk.cross(x_disk) / in_plane;
    }
    const double tsr = v_dot_x == 0 ? 0.0 : omega * r_max / v_dot_x;
    const double weight = induction_weight(tsr);

    for (std::size_t k = 0; k < nb; ++k) {
        const Vec root_z = motion.blades[k].root_axes.col(2);
        const double a = -root_z.dot(y_disk), c = root_z.dot(z_disk);
        const double psi = nearly_zero(a) && nearly_zero(c) ? 0.0 : std::atan2(a, c);
        auto& nodes = result_.blades[k];
        double r_tip = 0;
        for (const auto& n : nodes) r_tip = std::max(r_tip, n.r_local);
        for (NodeResult& n : nodes) {
            n.input.chi0 = chi0;
            n.input.psi = psi;
            n.input.tip_ratio = n.r_local / r_tip;
            n.input.weight = weight;
        }
    }
    RotorResult& r = result_;
    r.r_max = r_max;
    r.tsr = tsr;
    r.skew = chi0;
    r.v_avg_xh = v_dot_x;
}

} // namespace yamsc::aero

namespace yamsc::aero {

const RotorResult& BemRotor::integrate(const RotorMotion& motion) {
    const Vec x_disk = motion.hub_axes.col(0);
    const double omega = motion.hub_angular_velocity.dot(x_disk);
    const double rho = input_.air_density;
    Vec force = Vec::Zero(), moment = Vec::Zero();
    RotorResult& r = mutable_result();
    const std::size_t nb = std::min(motion.blades.size(), result_.blades.size());
    for (std::size_t k = 0; k < nb; ++k) {
        const auto& nodes = result_.blades[k];
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
            moment += (p.position - motion.hub_position).cross(lp) +
                      (q.position - motion.hub_position).cross(lq) + len / 2.0 * (mp + mq);
        }
    }
    r.loads = true;
    const double v_dot_x = r.v_avg_xh, r_max = r.r_max;
    r.fxh = force.dot(x_disk);
    r.mxh = moment.dot(x_disk);
    r.power = omega * r.mxh;
    if (std::abs(v_dot_x) < 0.04) {
        r.cp = r.ct = r.cq = 0;
    } else {
        const double q = 0.5 * rho * pi * r_max * r_max * v_dot_x * v_dot_x;
        r.cp = r.power / (q * v_dot_x);
        r.cq = r.mxh / (q * r_max);
        r.ct = r.fxh / q;
    }
    return r;
}

void BemRotor::freeze_wake() {
    if (!solved_) throw std::logic_error("blade elements: a frozen wake needs an evaluation first");
    const RotorResult& current = result();
    frozen_.assign(current.blades.size(), {});
    for (std::size_t k = 0; k < current.blades.size(); ++k)
        for (const NodeResult& n : current.blades[k])
            frozen_[k].push_back({n.bem.a * n.vx, n.bem.ap * n.vy});
}

void BemRotor::frozen_element(NodeResult& n, const Induced& induced) const {
    const double a = nearly_zero(n.vx) ? 0.0 : induced.axial / n.vx;
    const double ap = nearly_zero(n.vy) ? 0.0 : induced.tangential / n.vy;
    element_loads(n.input, options_, input_.air_density, a, ap, n.bem);
}

} // namespace yamsc::aero
