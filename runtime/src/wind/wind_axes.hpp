#pragma once
// InflowWind's turn of a point into the wind's axes (InflowWind_SetParameters'
// RotToWind): R_y(-upflow) R_z(-direction), rows as written there; every kind of
// field turns its points about [0, 0, RefHt] by it and its velocities back by
// the transpose.
#include <Eigen/Core>

#include <cmath>

namespace yamsc::runtime {

inline Eigen::Matrix3d to_wind_axes(double direction, double upflow) {
    const double cy = std::cos(-upflow), sy = std::sin(-upflow);
    const double cz = std::cos(-direction), sz = std::sin(-direction);
    Eigen::Matrix3d m;
    m << cy * cz, cy * sz, -sy, -sz, cz, 0.0, sy * cz, sy * sz, cy;
    return m;
}

} // namespace yamsc::runtime
