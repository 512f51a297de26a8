#pragma once
// InflowWind's uniform wind field (WindType 1, steady, and WindType 2, a uniform
// wind file), as IfW_SteadyWind_Init, IfW_UniformWind_Init,
// UniformField_InterpLinear, UniformField_GetVel and InflowWind_SetParameters
// compute it (OpenFAST v4/v5):
// - the columns are interpolated linearly in time and held beyond the ends
//   (the direction unwrapped so that successive samples differ by less than pi);
// - the point is first turned into the wind's axes about [0, 0, RefHt]:
//   p' = M (p - [0 0 H]) + [0 0 H], M = R_y(-VFlowAng) R_z(-PropagationDir), and
//   the velocity found there turned back by M^T (PropagationDir is
//   meteorological: a positive one turns the wind from +X towards -Y);
// - at p' (zero wind at or below the ground, z' <= 0):
//   V1 = V ((z'/H)^PLexp + (ShrH (y' cos D + x' sin D) + LinShrV (z' - H)) / RefLength) + Gust,
//   turned by the upflow column A: U = cos A V1 - sin A Vz, W = sin A V1 + cos A Vz,
//   v' = [U cos D, -U sin D, W], D the direction column (meteorological too).
// yamsc computes in double precision (InflowWind in single).
#include "yamsc/wind/wind_field.hpp"

#include <vector>

namespace yamsc::runtime {

/// The samples of the uniform wind file's columns (angles in radians, InflowWind's order).
struct UniformWindSamples {
    std::vector<double> time, speed, direction, vertical, horizontal_shear, power_law,
        linear_vertical_shear, gust, upflow;
};

struct UniformWindSetup {
    UniformWindSamples samples;
    double reference_height = 0;    // RefHt (RefHt_Uni) [m], > 0
    double reference_length = 1;    // RefLength [m] (1 for WindType 1), > 0
    double propagation_dir = 0;     // PropagationDir [rad]
    double vertical_flow_angle = 0; // VFlowAng [rad]
};

/// WindType 1: one sample, HWindSpeed with the power law PLexp.
UniformWindSamples steady_wind(double speed, double power_law);

class UniformField final : public WindField {
public:
    /// Throws std::invalid_argument on samples of different lengths, times not
    /// rising, a height or length not positive.
    explicit UniformField(UniformWindSetup setup);
    double reference_speed(double t) const override;
    Eigen::Vector3d velocity(double t, const Eigen::Vector3d& position,
                             double reference_speed) const override;
    bool steady() const override { return s_.samples.time.size() == 1; }
    void velocities(double t, const Eigen::Vector3d* positions, std::size_t n,
                    double reference_speed, Eigen::Vector3d* out) const override;
    const UniformWindSetup& setup() const { return s_; }

    /// The columns at time t (InflowWind's UniformField_Interp operating point).
    struct Point {
        double speed, direction, vertical, horizontal_shear, power_law, linear_vertical_shear, gust,
            upflow;
    };
    Point at(double t) const;

private:
    /// What velocity() needs of time t: the columns and their sines and cosines.
    struct Instant {
        Point p;
        double v, cos_dir, sin_dir, cos_up, sin_up;
    };
    Instant instant(double t, double reference_speed) const;
    Eigen::Vector3d velocity(const Instant& at, const Eigen::Vector3d& position) const;

    UniformWindSetup s_;
    Eigen::Matrix3d to_wind_; // M: ground axes to the wind's
    bool rotated_ = false;
};

} // namespace yamsc::runtime
