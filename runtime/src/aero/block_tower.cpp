#include "block_tower.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace yamsc::aero {

namespace {

using Eigen::Vector3d;

Vec3 vec3(const Vector3d& v) {
    return {v.x(), v.y(), v.z()};
}
Vector3d eigen(const Vec3& v) {
    return {v[0], v[1], v[2]};
}

/// AeroDyn's tower nodes as points of the tower body, `height` above its
/// origin each: between the two SID nodes around that height (following the
/// deflection as the structure's own nodes do), the end node's shapes beyond
/// the ends; on a rigid tower (no nodes) fixed points on its z axis.
std::vector<runtime::BodyPoint> tower_points(const std::vector<runtime::BodyPoint>& nodes,
                                             const std::vector<double>& heights) {
    std::vector<runtime::BodyPoint> sorted = nodes;
    std::sort(sorted.begin(), sorted.end(),
              [](const runtime::BodyPoint& a, const runtime::BodyPoint& b) {
                  return a.origin.z() < b.origin.z();
              });
    std::vector<runtime::BodyPoint> points;
    for (double h : heights) {
        runtime::BodyPoint p;
        if (sorted.size() == 1) p = sorted.front();
        if (sorted.size() >= 2) {
            std::size_t i = 0;
            while (i + 2 < sorted.size() && sorted[i + 1].origin.z() < h) ++i;
            const double z0 = sorted[i].origin.z(), z1 = sorted[i + 1].origin.z();
            const double s = std::clamp((h - z0) / (z1 - z0), 0.0, 1.0);
            p = runtime::blend(sorted[i], sorted[i + 1], s);
        }
        p.origin = Vector3d(0, 0, h);
        points.push_back(std::move(p));
    }
    return points;
}

} // namespace

BlockTower::BlockTower(const RotorInput& rotor, const TowerChannels& channels)
    : rotor_(rotor), channels_(channels) {
    influence_.potential = rotor.tower_potential;
    influence_.shadow = rotor.tower_shadow;
    drag_on_ = rotor.tower_drag && !channels.outputs.empty();
    if (!used()) return;
    if (rotor.tower.size() < 2)
        throw std::invalid_argument("blade elements: the tower's influence or drag needs the "
                                    "AeroDyn file's tower table (two nodes at least)");
    const std::size_t n = rotor.tower.size();
    state_ = undeflected_tower(rotor.tower, {0, 0, 0});
    for (const TowerNode& t : rotor.tower) reference_.push_back({0, 0, t.elevation});
    drag_.resize(n);
    lumped_force_.resize(n);
    lumped_moment_.resize(n);
    if (!channels.points.empty()) modes_ = channels.points.front().phi.size();
    std::size_t nodes = 0;
    for (const auto& b : rotor.blades) nodes += b.size();
    blade_points_.resize(nodes);
    blade_winds_.resize(nodes);
}

void BlockTower::read(const double* values, const FreeWind& wind) {
    if (!used()) return;
    const std::size_t n = rotor_.tower.size();
    if (channels_.outputs.empty()) { // the undeflected tower, at rest
        for (std::size_t j = 0; j < n; ++j)
            state_.wind[j] = vec3(wind.at(eigen(state_.position[j])));
        return;
    }
    runtime::read_body_frame(values, modes_, frame_);
    if (points_.empty()) {
        // TwrElev is measured from the ground, the tower body from its origin
        // (ElastoDyn's TowerBsHt): the origin's elevation where the tower starts.
        std::vector<double> heights;
        for (const TowerNode& t : rotor_.tower) heights.push_back(t.elevation - frame_.r.z());
        points_ = tower_points(channels_.points, heights);
    }
    for (std::size_t j = 0; j < n; ++j) {
        const runtime::PointMotion pm = runtime::point_motion(frame_, points_[j]);
        state_.position[j] = vec3(pm.r);
        state_.axis[j] = vec3(pm.R.col(2));
        state_.velocity[j] = vec3(pm.v);
        state_.wind[j] = vec3(wind.at(pm.r));
    }
}

void BlockTower::disturb(RotorMotion& motion) {
    if (!influence_.active()) return;
    std::size_t i = 0;
    for (const auto& b : motion.blades)
        for (std::size_t j = 0; j < b.position.size(); ++j) {
            blade_points_[i] = vec3(b.position[j]);
            blade_winds_[i++] = vec3(b.wind[j]);
        }
    const double clearance = disturb_winds(influence_, rotor_.tower, state_, blade_points_.data(),
                                           blade_winds_.data(), i);
    if (clearance <= 0)
        throw std::invalid_argument("blade elements: tower strike (a blade node " +
                                    std::to_string(-clearance) + " m inside the tower's surface)");
    i = 0;
    for (auto& b : motion.blades)
        for (Vector3d& w : b.wind) w = eigen(blade_winds_[i++]);
}

void BlockTower::write_loads(double* loads) {
    if (!drag_on_) return;
    const std::size_t n = rotor_.tower.size();
    tower_drag(rotor_.tower, state_, rotor_.air_density, drag_.data());
    lump_line_loads(reference_.data(), state_.position.data(), drag_.data(), n,
                    lumped_force_.data(), lumped_moment_.data());
    load_.force.setZero();
    load_.moment.setZero();
    load_.modal.assign(modes_, 0.0);
    for (std::size_t j = 0; j < n; ++j)
        runtime::add_point_load(frame_, points_[j], eigen(lumped_force_[j]),
                                eigen(lumped_moment_[j]), load_);
    for (int c = 0; c < 3; ++c) {
        loads[c] = load_.force[c];
        loads[3 + c] = load_.moment[c];
    }
    for (std::size_t k = 0; k < modes_; ++k) loads[6 + k] = load_.modal[k];
}

} // namespace yamsc::aero
