#include "beam/sampled_beam.hpp"

#include <cmath>

namespace yamsc::beam {

namespace {

/// A station property, piecewise linear in s (constant beyond the first and last station).
double interpolate(const std::vector<Station>& st, double s, double Station::*field) {
    if (s <= st.front().s) return st.front().*field;
    for (std::size_t i = 1; i < st.size(); ++i)
        if (s <= st[i].s) {
            const double t = (s - st[i - 1].s) / (st[i].s - st[i - 1].s);
            return (1 - t) * (st[i - 1].*field) + t * (st[i].*field);
        }
    return st.back().*field;
}

/// d^order/dz^order of sum_p c_p (z/L)^p.
double polynomial(const std::vector<double>& c, double z, double L, int order) {
    const double x = z / L;
    double v = 0;
    for (std::size_t p = static_cast<std::size_t>(order); p < c.size(); ++p) {
        double factor = c[p];
        for (int d = 0; d < order; ++d) factor *= static_cast<double>(p) - d;
        v += factor * std::pow(x, static_cast<double>(p) - order);
    }
    return v / std::pow(L, order);
}

/// The principal direction of mode displacement `direction` (0: x, 1: y) under twist.
Vec3 principal(int direction, double twist) {
    const double c = std::cos(twist), s = std::sin(twist);
    return direction == 0 ? Vec3{c, s, 0} : Vec3{-s, c, 0};
}

/// The mode's polynomial is its curvature along a principal axis (ElastoDyn's
/// twisted shape functions, "TwistedSF"): the body-axes curvature is that axis
/// times phi'', and the slope and the displacement are its running integrals from
/// the clamped root. Without twist this is exactly Phi = e_dir phi (paper B1-B2).
SampledMode sample_mode(const Mode& mode, double L, const Grid& grid,
                        const std::vector<double>& twist, bool integrated) {
    const std::size_t n = grid.size();
    SampledMode out;
    out.curvature.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        out.curvature[i] =
            polynomial(mode.coeffs, grid.z()[i], L, 2) * principal(mode.direction, twist[i]);
    if (!integrated) { // the polynomial's own values (ElastoDyn's tower: SHP)
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 axis = principal(mode.direction, twist[i]);
            out.phi.push_back(polynomial(mode.coeffs, grid.z()[i], L, 0) * axis);
            out.slope.push_back(polynomial(mode.coeffs, grid.z()[i], L, 1) * axis);
        }
        return out;
    }
    const Vec3 root_axis = principal(mode.direction, twist.front());
    const Vec3 root_value = polynomial(mode.coeffs, 0, L, 0) * root_axis;
    const Vec3 root_slope = polynomial(mode.coeffs, 0, L, 1) * root_axis;
    out.slope.assign(n, root_slope);
    out.phi.assign(n, root_value);
    for (std::size_t a = 0; a < 3; ++a) {
        std::vector<double> f(n);
        for (std::size_t i = 0; i < n; ++i) f[i] = out.curvature[i][a];
        f = grid.running_integral(f);
        for (std::size_t i = 0; i < n; ++i) out.slope[i][a] += f[i];
        for (std::size_t i = 0; i < n; ++i) f[i] = out.slope[i][a];
        f = grid.running_integral(f);
        for (std::size_t i = 0; i < n; ++i) out.phi[i][a] += f[i];
    }
    return out;
}

std::vector<double> station_breaks(const Beam& beam) {
    std::vector<double> breaks;
    for (const Station& s : beam.stations) breaks.push_back(s.s * beam.length);
    return breaks;
}

} // namespace

SampledBeam sample_beam(const Beam& beam) {
    SampledBeam b{beam.elements > 0
                      ? Grid::elements(beam.length, beam.elements)
                      : Grid(beam.length, beam.integration_stations, station_breaks(beam)),
                  {},
                  {},
                  {},
                  {},
                  {},
                  {}};
    for (double z : b.grid.z()) {
        const double s = z / beam.length;
        b.m.push_back(interpolate(beam.stations, s, &Station::mass_per_length));
        b.EI_x.push_back(interpolate(beam.stations, s, &Station::EI_x));
        b.EI_y.push_back(interpolate(beam.stations, s, &Station::EI_y));
        b.twist.push_back(interpolate(beam.stations, s, &Station::twist));
        b.s0.push_back({0, 0, z});
    }
    for (const Mode& mode : beam.modes)
        b.modes.push_back(sample_mode(mode, beam.length, b.grid, b.twist,
                                      beam.integrated_shapes || beam.elements == 0));
    return b;
}

} // namespace yamsc::beam
