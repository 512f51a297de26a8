#include "yamsc/wind/uniform_field.hpp"

#include "wind_axes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace yamsc::runtime {

namespace {

constexpr double pi = 3.14159265358979323846;

} // namespace

UniformWindSamples steady_wind(double speed, double power_law) {
    UniformWindSamples s;
    s.time = {0.0};
    s.speed = {speed};
    s.power_law = {power_law};
    s.direction = s.vertical = s.horizontal_shear = s.linear_vertical_shear = s.gust =
        s.upflow = {0.0};
    return s;
}

UniformField::UniformField(UniformWindSetup setup) : s_(std::move(setup)) {
    UniformWindSamples& w = s_.samples;
    const std::size_t n = w.time.size();
    for (const std::vector<double>* c :
         {&w.speed, &w.direction, &w.vertical, &w.horizontal_shear, &w.power_law,
          &w.linear_vertical_shear, &w.gust, &w.upflow})
        if (c->size() != n || n == 0)
            throw std::invalid_argument("uniform wind: every column needs one value per time");
    for (std::size_t i = 1; i < n; ++i)
        if (!(w.time[i] > w.time[i - 1]))
            throw std::invalid_argument("uniform wind: times must increase");
    if (!(s_.reference_height > 0))
        throw std::invalid_argument("uniform wind: the reference height must be positive");
    if (!(s_.reference_length > 0))
        throw std::invalid_argument("uniform wind: the reference length must be positive");
    // IfW_UniformWind_Init: no jump of the direction by pi or more between samples.
    for (std::size_t i = 1; i < n; ++i)
        for (int tries = 0; tries < 100; ++tries) {
            const double diff = w.direction[i] - w.direction[i - 1];
            if (std::abs(diff) < pi) break;
            w.direction[i] -= std::copysign(2 * pi, diff);
        }
    // InflowWind_SetParameters keeps PropagationDir within [-pi, pi] (MPi2Pi).
    s_.propagation_dir = std::remainder(s_.propagation_dir, 2 * pi);
    rotated_ = s_.propagation_dir != 0 || s_.vertical_flow_angle != 0;
    to_wind_ = to_wind_axes(s_.propagation_dir, s_.vertical_flow_angle);
}

UniformField::Point UniformField::at(double t) const {
    const UniformWindSamples& w = s_.samples;
    const std::size_t n = w.time.size();
    std::size_t i = 0;
    double a = 0;
    if (n == 1 || t < w.time.front()) {
        i = 0;
    } else if (t >= w.time.back()) {
        i = n - 1;
    } else {
        i = static_cast<std::size_t>(std::upper_bound(w.time.begin(), w.time.end(), t) -
                                     w.time.begin()) -
            1;
        a = (t - w.time[i]) / (w.time[i + 1] - w.time[i]);
    }
    auto value = [&](const std::vector<double>& c) {
        return a == 0 ? c[i] : c[i] * (1 - a) + c[i + 1] * a;
    };
    return {value(w.speed),     value(w.direction),
            value(w.vertical),  value(w.horizontal_shear),
            value(w.power_law), value(w.linear_vertical_shear),
            value(w.gust),      value(w.upflow)};
}

double UniformField::reference_speed(double t) const {
    const Point p = at(t);
    return p.speed + p.gust;
}

UniformField::Instant UniformField::instant(double t, double reference_speed) const {
    const Point p = at(t);
    // The reference speed V + Gust given: V replaced, the gust kept.
    return {p,
            reference_speed - p.gust,
            std::cos(p.direction),
            std::sin(p.direction),
            std::cos(p.upflow),
            std::sin(p.upflow)};
}

Eigen::Vector3d UniformField::velocity(const Instant& at, const Eigen::Vector3d& position) const {
    const double h = s_.reference_height;
    const Eigen::Vector3d ref(0, 0, h);
    const Eigen::Vector3d p =
        rotated_ ? Eigen::Vector3d(to_wind_ * (position - ref) + ref) : position;
    if (!(p.z() > 0)) return Eigen::Vector3d::Zero(); // at or below the ground
    const Point& op = at.p;
    const double ch = at.cos_dir, sh = at.sin_dir;
    const double profile = op.power_law == 0 ? 1.0 : std::pow(p.z() / h, op.power_law);
    const double v1 = at.v * (profile + (op.horizontal_shear * (p.y() * ch + p.x() * sh) +
                                         op.linear_vertical_shear * (p.z() - h)) /
                                            s_.reference_length) +
                      op.gust;
    const double u = at.cos_up * v1 - at.sin_up * op.vertical;
    const double w = at.sin_up * v1 + at.cos_up * op.vertical;
    const Eigen::Vector3d vel(u * ch, -u * sh, w);
    return rotated_ ? Eigen::Vector3d(to_wind_.transpose() * vel) : vel;
}

Eigen::Vector3d UniformField::velocity(double t, const Eigen::Vector3d& position,
                                       double reference_speed) const {
    return velocity(instant(t, reference_speed), position);
}

void UniformField::velocities(double t, const Eigen::Vector3d* positions, std::size_t n,
                              double reference_speed, Eigen::Vector3d* out) const {
    const Instant at = instant(t, reference_speed);
    for (std::size_t i = 0; i < n; ++i) out[i] = velocity(at, positions[i]);
}

} // namespace yamsc::runtime
