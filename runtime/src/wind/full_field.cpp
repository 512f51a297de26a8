#include "yamsc/wind/full_field.hpp"

#include "wind_axes.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace yamsc::runtime {

namespace {

/// InflowWind's GridTol: a point this close (in cells) outside an edge is on it.
constexpr double grid_tol = 1.0e-3;

/// Fortran's AINT: the integer part towards zero.
double aint(double x) {
    return std::trunc(x);
}

/// Two neighbouring samples and the weight of the second (InflowWind's indices, 1-based).
struct Bounds {
    int lo = 0, hi = 0;
    double w = 0;
};

std::string number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

} // namespace

FullField::FullField(FullFieldSetup setup) : s_(std::move(setup)) {
    const FullFieldSetup& s = s_;
    const auto need = [&](bool ok, const char* what) {
        if (!ok) throw std::invalid_argument(s.source + ": " + what);
    };
    need(s.ny >= 2 && s.nz >= 2 && s.nt >= 2 && s.n_tower >= 0, "a grid of 2 x 2 x 2 or more");
    need(s.grid.size() == std::size_t(s.nt) * s.ny * s.nz * 3 &&
             s.tower.size() == std::size_t(s.nt) * s.n_tower * 3,
         "as many values as the grid's points");
    need(s.dy > 0 && s.dz > 0 && s.dt > 0, "positive spacings");
    need(s.mean_speed > 0, "a positive mean speed");
    need(s.reference_height > 0, "a positive reference height");
    inv_dy_ = 1.0 / s.dy;
    inv_dz_ = 1.0 / s.dz;
    half_width_ = 0.5 * (s.ny - 1) / inv_dy_;
    inv_mean_ = 1.0 / s.mean_speed;
    rate_ = 1.0 / s.dt;
    rotated_ = s.propagation_dir != 0 || s.vertical_flow_angle != 0;
    to_wind_ = to_wind_axes(s.propagation_dir, s.vertical_flow_angle);

    // The mean profile: u' over the times and y' per row, with the box's profile.
    std::vector<double> row(static_cast<std::size_t>(s.nz), 0.0);
    for (int it = 0; it < s.nt; ++it)
        for (int iz = 0; iz < s.nz; ++iz)
            for (int iy = 0; iy < s.ny; ++iy)
                row[iz] += s.grid[((std::size_t(it) * s.nz + iz) * s.ny + iy) * 3];
    for (int iz = 0; iz < s.nz; ++iz)
        row[iz] = row[iz] / (double(s.nt) * s.ny) + mean_profile(s.z_bottom + iz / inv_dz_);
    shape_ = row;
    const double zr = (s.reference_height - s.z_bottom) * inv_dz_;
    need(zr >= -grid_tol && zr <= s.nz - 1 + grid_tol, "a grid that reaches the reference height");
    const int k = std::min(std::max(int(std::floor(zr)), 0), s.nz - 2);
    const double at_reference = row[k] + (zr - k) * (row[k + 1] - row[k]);
    for (double& v : shape_) v = at_reference != 0 ? v / at_reference : 1.0;

    // The reference speed at the times the grid's samples pass [0, 0, RefHt].
    const Eigen::Vector3d hub(0, 0, s.reference_height);
    const int samples = s.periodic ? s.nt + 1 : s.nt;
    for (int i = 0; i < samples; ++i) {
        const double t = i * s.dt - s.init_x * inv_mean_;
        const Eigen::Vector3d v = interpolate(t, hub);
        hub_.time.push_back(t);
        hub_.speed.push_back(std::hypot(v.x(), v.y()));
    }
    if (s.periodic) hub_.period = s.nt * s.dt;
}

double FullField::mean_profile(double z) const {
    if (z <= 0) return 0;
    const double h = s_.reference_height, u = s_.mean_speed;
    switch (s_.profile) {
    case MeanProfile::power_law:
        return u * std::pow(z / h, s_.power_law);
    case MeanProfile::logarithmic:
        return h != s_.roughness ? u * std::log(z / s_.roughness) / std::log(h / s_.roughness) : 0;
    case MeanProfile::constant:
        return u;
    case MeanProfile::none:
        break;
    }
    return 0;
}

void FullField::outside(double t, const Eigen::Vector3d& p, const std::string& what) const {
    throw std::runtime_error(s_.source + ": the wind at t = " + number(t) + " s at (" +
                             number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) +
                             ") m (wind axes): " + what);
}

Eigen::Vector3d FullField::in_wind_axes(double t, const Eigen::Vector3d& p, double& shape) const {
    const FullFieldSetup& s = s_;
    shape = 0;
    if (p.z() <= 0) return Eigen::Vector3d::Zero();

    // GetBoundsT: the grid time that passes x' at t.
    const double shifted = t + (s.init_x - p.x()) * inv_mean_;
    double tg = shifted * rate_;
    if (s.periodic) {
        tg = tg - std::floor(tg / s.nt) * s.nt;
        tg = tg - std::floor(tg / s.nt) * s.nt;
    }
    Bounds bt;
    bt.lo = static_cast<int>(std::floor(tg)) + 1;
    bt.hi = bt.lo + 1;
    double xi_t = 2.0 * (tg - aint(tg)) - 1.0;
    if (bt.lo >= 1 && bt.hi <= s.nt) {
    } else if (bt.lo == s.nt) {
        if (s.periodic) {
            bt.hi = 1;
        } else if (xi_t <= grid_tol) {
            bt.hi = bt.lo;
            xi_t = -1.0;
        } else {
            bt.lo = s.nt - 1;
            bt.hi = s.nt;
        }
    } else {
        outside(t, p,
                "the grid's times are exhausted (grid time " + number(shifted) + " s; the grid " +
                    "holds " + number((s.periodic ? s.nt : s.nt - 1) * s.dt) +
                    " s from t = " + number(-s.init_x * inv_mean_) + " s at x' = 0)");
    }
    bt.w = (xi_t + 1.0) / 2.0;

    // GetBoundsY.
    const auto bounds_y = [&]() {
        const double yg = (p.y() + half_width_) * inv_dy_ + 1;
        Bounds b;
        b.lo = static_cast<int>(std::floor(yg));
        b.hi = b.lo + 1;
        double d = yg - aint(yg);
        if (b.lo >= 1 && b.hi <= s.ny) {
        } else if (b.lo == 0 && d >= 1.0 - grid_tol) {
            b.lo = 1, b.hi = 2, d = 0;
        } else if (b.lo == s.ny && d <= grid_tol) {
            b.lo = s.ny - 1, b.hi = s.ny, d = 1;
        } else {
            outside(t, p,
                    "y' beyond the grid's [" + number(-half_width_) + ", " + number(half_width_) +
                        "] m");
        }
        b.w = d;
        return b;
    };
    const auto grid = [&](int it, int iz, int iy, int c) {
        return double(s.grid[((std::size_t(it - 1) * s.nz + (iz - 1)) * s.ny + (iy - 1)) * 3 + c]);
    };
    const auto tower = [&](int it, int k, int c) {
        return k > s.n_tower ? 0.0
                             : double(s.tower[(std::size_t(it - 1) * s.n_tower + (k - 1)) * 3 + c]);
    };

    // GetBoundsZ.
    const double zg = (p.z() - s.z_bottom) * inv_dz_ + 1;
    Bounds bz;
    bz.lo = static_cast<int>(std::floor(zg));
    bz.hi = bz.lo + 1;
    double dz = zg - aint(zg);
    bool in_grid = false;
    if (bz.lo >= 1 && bz.hi <= s.nz) {
        in_grid = true;
    } else if (bz.lo < 1 && bz.lo == 0 && dz >= 1.0 - grid_tol) {
        in_grid = true;
        bz.lo = 1, bz.hi = 2, dz = 0;
    } else if (bz.lo < 1) {
        if (s.to_ground) {
            // Between the ground (row 0, zero) and the grid's bottom row.
            const Bounds by = bounds_y();
            const double w = p.z() / s.z_bottom;
            Eigen::Vector3d v;
            for (int c = 0; c < 3; ++c) {
                const auto row = [&](int it) {
                    return (1 - by.w) * grid(it, 1, by.lo, c) + by.w * grid(it, 1, by.hi, c);
                };
                v[c] = w * ((1 - bt.w) * row(bt.lo) + bt.w * row(bt.hi));
            }
            shape = shape_[0] * w;
            v.x() += mean_profile(p.z());
            return v;
        }
        if (s.n_tower == 0)
            outside(t, p,
                    "z' below the grid's bottom (" + number(s.z_bottom) +
                        " m) and the file has no tower points");
        // The tower points, top (k = 1, at the grid's bottom) down, then the ground.
        int k = static_cast<int>(-(zg - 1)) + 1;
        double w = 0;
        if (k >= s.n_tower) {
            k = s.n_tower;
            w = 1 - p.z() / (s.z_bottom - (k - 1) / inv_dz_);
        } else {
            w = (2 - k) - zg;
        }
        Eigen::Vector3d v;
        for (int c = 0; c < 3; ++c)
            v[c] = (1 - bt.w) * ((1 - w) * tower(bt.lo, k, c) + w * tower(bt.lo, k + 1, c)) +
                   bt.w * ((1 - w) * tower(bt.hi, k, c) + w * tower(bt.hi, k + 1, c));
        shape = shape_[0] * p.z() / s.z_bottom;
        return v;
    } else if (bz.lo == s.nz && dz <= grid_tol) {
        in_grid = true;
        bz.lo = s.nz - 1, bz.hi = s.nz, dz = 1;
    } else {
        outside(t, p,
                "z' above the grid's top (" + number(s.z_bottom + (s.nz - 1) / inv_dz_) + " m)");
    }
    static_cast<void>(in_grid);
    bz.w = dz;
    const Bounds by = bounds_y();
    Eigen::Vector3d v;
    for (int c = 0; c < 3; ++c) {
        const auto plane = [&](int it) {
            return (1 - bz.w) *
                       ((1 - by.w) * grid(it, bz.lo, by.lo, c) + by.w * grid(it, bz.lo, by.hi, c)) +
                   bz.w *
                       ((1 - by.w) * grid(it, bz.hi, by.lo, c) + by.w * grid(it, bz.hi, by.hi, c));
        };
        v[c] = (1 - bt.w) * plane(bt.lo) + bt.w * plane(bt.hi);
    }
    shape = (1 - bz.w) * shape_[bz.lo - 1] + bz.w * shape_[bz.hi - 1];
    v.x() += mean_profile(p.z());
    return v;
}

Eigen::Vector3d FullField::at(double t, const Eigen::Vector3d& p, double delta) const {
    const Eigen::Vector3d hub(0, 0, s_.reference_height);
    const Eigen::Vector3d q = rotated_ ? Eigen::Vector3d(to_wind_ * (p - hub) + hub) : p;
    double shape = 0;
    Eigen::Vector3d v = in_wind_axes(t, q, shape);
    v.x() += delta * shape;
    return rotated_ ? Eigen::Vector3d(to_wind_.transpose() * v) : v;
}

Eigen::Vector3d FullField::interpolate(double t, const Eigen::Vector3d& position) const {
    return at(t, position, 0.0);
}

Eigen::Vector3d FullField::velocity(double t, const Eigen::Vector3d& position,
                                    double reference_speed) const {
    return at(t, position, reference_speed - hub_(t));
}

void FullField::velocities(double t, const Eigen::Vector3d* positions, std::size_t n,
                           double reference_speed, Eigen::Vector3d* out) const {
    const double delta = reference_speed - hub_(t);
    for (std::size_t i = 0; i < n; ++i) out[i] = at(t, positions[i], delta);
}

} // namespace yamsc::runtime
