// The tower's own drag (AeroDyn's ADTwr_CalcOutput, TwrAero).
#include <cmath>

#include "yamsc/aero/tower_influence.hpp"

namespace yamsc::aero {
namespace {

// The wind relative to the node, its part normal to the node's axis. AeroDyn
// takes the components along the node's x and y axes; with an orthonormal
// orientation that is the same vector.
Vec3 normal_relative_wind(const Vec3& wind, const Vec3& velocity, const Vec3& axis) {
    const Vec3 v{wind[0] - velocity[0], wind[1] - velocity[1], wind[2] - velocity[2]};
    const double along = v[0] * axis[0] + v[1] * axis[1] + v[2] * axis[2];
    return {v[0] - along * axis[0], v[1] - along * axis[1], v[2] - along * axis[2]};
}

double norm(const Vec3& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

} // namespace

Vec3 tower_drag_per_length(const TowerNode& node, double air_density, const Vec3& wind,
                           const Vec3& velocity, const Vec3& axis) {
    const Vec3 normal = normal_relative_wind(wind, velocity, axis);
    const double speed = norm(normal);
    const double q = 0.5 * node.cd * air_density * node.diameter * speed;
    return {q * normal[0], q * normal[1], q * normal[2]};
}

std::array<double, 9> tower_drag_velocity_jacobian(const TowerNode& node, double air_density,
                                                   const Vec3& wind, const Vec3& velocity,
                                                   const Vec3& axis) {
    const Vec3 n = normal_relative_wind(wind, velocity, axis);
    const double speed = norm(n);
    std::array<double, 9> jacobian{};
    if (speed == 0) return jacobian;
    const double k = 0.5 * node.cd * air_density * node.diameter;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double projector = (i == j ? 1.0 : 0.0) - axis[i] * axis[j];
            jacobian[3 * i + j] = -k * (speed * projector + n[i] * n[j] / speed);
        }
    return jacobian;
}

void tower_drag(const std::vector<TowerNode>& table, const TowerState& state, double air_density,
                Vec3* force) {
    for (std::size_t j = 0; j < table.size(); ++j)
        force[j] = tower_drag_per_length(table[j], air_density, state.wind[j], state.velocity[j],
                                         state.axis[j]);
}

} // namespace yamsc::aero
