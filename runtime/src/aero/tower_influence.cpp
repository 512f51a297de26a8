// AeroDyn's tower influence on the blades' wind: getLocalTowerProps (nearest
// element, else nearest node), CalculateTowerInfluence, TwrInfl.
#include "yamsc/aero/tower_influence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace yamsc::aero {
namespace {

constexpr double pi = 3.14159265358979323846;

Vec3 operator-(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 operator+(const Vec3& a, const Vec3& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Vec3 operator*(double s, const Vec3& a) {
    return {s * a[0], s * a[1], s * a[2]};
}
double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// NWTC's EqualRealNos: equal but for the last two significant digits.
template <class Real> bool nearly_equal(Real a, Real b) {
    const Real tolerance = Real(100) * std::numeric_limits<Real>::epsilon() / Real(2);
    return std::abs(a - b) <= std::max(std::abs(a + b), Real(1)) * tolerance;
}

// The frame of the relative wind normal to the tower, and the normalized
// coordinates of r in it (zbar left for the caller). AeroDyn leaves the
// frame zero, w zero and xbar 1 when that wind vanishes: no influence.
bool set_frame(TowerProjection& p, const Vec3& z_hat, const Vec3& relative_wind) {
    const Vec3 normal = relative_wind - dot(relative_wind, z_hat) * z_hat;
    const double size = std::sqrt(dot(normal, normal));
    if (nearly_equal(size, 0.0)) {
        p.x_hat = p.y_hat = p.z_hat = Vec3{};
        p.w = 0;
        p.xbar = 1;
        p.ybar = 0;
        p.zbar = 0;
        return false;
    }
    p.z_hat = z_hat;
    p.x_hat = (1 / size) * normal;
    p.y_hat = (1 / size) * cross(z_hat, relative_wind);
    p.w = dot(relative_wind, p.x_hat);
    p.xbar = 2 / p.diameter * dot(p.r, p.x_hat);
    p.ybar = 2 / p.diameter * dot(p.r, p.y_hat);
    p.zbar = 0;
    return true;
}

// Fraction along the element, or a negative number when the point does not
// project orthogonally onto it. AeroDyn rounds to single precision to snap
// points just beyond an end onto it.
double element_fraction(const Vec3& p1, const Vec3& p2, const Vec3& point) {
    const Vec3 along = p2 - p1;
    const double s = dot(along, point - p1) / dot(along, along);
    if (s >= 0 && s <= 1) return s;
    const float rounded = static_cast<float>(s);
    if (nearly_equal(rounded, 1.0f)) return 1;
    if (nearly_equal(rounded, 0.0f)) return 0;
    return -1;
}

bool nearest_element(const std::vector<TowerNode>& table, const TowerState& state,
                     const Vec3& point, TowerProjection& p) {
    double best = std::numeric_limits<double>::max();
    bool found = false;
    for (std::size_t e = 0; e + 1 < table.size(); ++e) {
        const Vec3& p1 = state.position[e];
        const Vec3& p2 = state.position[e + 1];
        const double s = element_fraction(p1, p2, point);
        if (s < 0) continue;
        const Vec3 r = point - ((1 - s) * p1 + s * p2);
        const double distance = dot(r, r);
        if (distance < best) {
            best = distance;
            found = true;
            p.index = e;
            p.fraction = s;
            p.r = r;
        }
    }
    if (!found) return false;
    const std::size_t n1 = p.index, n2 = p.index + 1;
    const double s = p.fraction, s1 = 1 - s;
    const Vec3 v1 = state.wind[n1] - state.velocity[n1];
    const Vec3 v2 = state.wind[n2] - state.velocity[n2];
    p.on_element = true;
    p.diameter = s1 * table[n1].diameter + s * table[n2].diameter;
    p.cd = s1 * table[n1].cd + s * table[n2].cd;
    p.ti = s1 * table[n1].ti + s * table[n2].ti;
    const Vec3 along = state.position[n2] - state.position[n1];
    set_frame(p, (1 / std::sqrt(dot(along, along))) * along, s1 * v1 + s * v2);
    return true;
}

void nearest_node(const std::vector<TowerNode>& table, const TowerState& state, const Vec3& point,
                  TowerProjection& p) {
    double best = std::numeric_limits<double>::max();
    std::size_t node = 0;
    for (std::size_t j = 0; j < table.size(); ++j) {
        const Vec3 r = point - state.position[j];
        const double distance = dot(r, r);
        if (distance < best) {
            best = distance;
            node = j;
        }
    }
    p.on_element = false;
    p.index = node;
    p.fraction = 0;
    p.r = point - state.position[node];
    p.diameter = table[node].diameter;
    p.cd = table[node].cd;
    p.ti = table[node].ti;
    const bool end = node == 0 || node + 1 == table.size();
    if (!set_frame(p, state.axis[node], state.wind[node] - state.velocity[node]) || !end) return;
    // Beyond an end of the tower the influence fades over one radius.
    p.zbar = 2 / p.diameter * dot(p.r, p.z_hat);
    if (std::abs(p.zbar) < 1) {
        const double taper = std::cos(pi / 2 * p.zbar);
        p.xbar /= taper;
        p.ybar /= taper;
    } else {
        p.xbar = 1;
        p.ybar = 0;
    }
}

} // namespace

TowerState undeflected_tower(const std::vector<TowerNode>& table, const Vec3& base) {
    TowerState state;
    for (const TowerNode& node : table) {
        state.position.push_back({base[0], base[1], node.elevation});
        state.axis.push_back({0, 0, 1});
        state.wind.push_back({});
        state.velocity.push_back({});
    }
    return state;
}

TowerProjection project_onto_tower(const std::vector<TowerNode>& table, const TowerState& state,
                                   const Vec3& point) {
    TowerProjection p;
    if (!nearest_element(table, state, point, p)) nearest_node(table, state, point, p);
    p.clearance = std::sqrt(dot(p.r, p.r)) - 0.5 * p.diameter;
    // Far away the influence is negligible; inside or at the wall the
    // potential flow is singular: AeroDyn leaves the wind alone in both.
    p.disturbs = !(p.clearance > 20 * p.diameter) && !(p.clearance <= 0.01 * p.diameter);
    return p;
}

TowerDisturbance tower_disturbance(const TowerInfluenceModel& model, double xbar, double ybar,
                                   double zbar, double cd, double ti) {
    TowerDisturbance d;
    if (std::abs(zbar) < 1 && model.potential != TowerPotential::none) {
        // Bak et al. (EWEC 2001) shift the doublet 0.1 radius downwind and add
        // a source of strength Cd (the drag's momentum deficit).
        const double x = model.potential == TowerPotential::bak ? xbar + 0.1 : xbar;
        const double r2 = x * x + ybar * ybar;
        d.axial = (-x * x + ybar * ybar) / (r2 * r2);
        d.transverse = -2 * x * ybar / (r2 * r2);
        if (model.potential == TowerPotential::bak) {
            d.axial += cd * x / (2 * pi * r2);
            d.transverse += cd * ybar / (2 * pi * r2);
        }
    }
    double shadow = 0;
    if (xbar > 0 && std::abs(zbar) < 1) {
        if (model.shadow == TowerShadow::powles) {
            const double width = std::sqrt(std::sqrt(xbar * xbar + ybar * ybar));
            if (std::abs(ybar) < width) {
                const double c = std::cos(pi / 2 * ybar / width);
                shadow = -cd / width * c * c;
            }
        } else if (model.shadow == TowerShadow::eames) {
            const double spread = ti * xbar;
            shadow = -cd / (spread * std::sqrt(2 * pi)) *
                     std::exp(-0.5 * (ybar / spread) * (ybar / spread));
        }
    }
    // AeroDyn limits the deficit so that the wake never reverses the flow.
    d.axial += std::max(shadow, -0.5);
    return d;
}

DisturbedWind disturbed_wind(const TowerInfluenceModel& model, const std::vector<TowerNode>& table,
                             const TowerState& state, const Vec3& point, const Vec3& undisturbed) {
    DisturbedWind out;
    out.projection = project_onto_tower(table, state, point);
    out.wind = undisturbed;
    const TowerProjection& p = out.projection;
    if (!p.disturbs) return out;
    const TowerDisturbance d = tower_disturbance(model, p.xbar, p.ybar, p.zbar, p.cd, p.ti);
    out.wind = undisturbed + (d.axial * p.w) * p.x_hat + (d.transverse * p.w) * p.y_hat;
    return out;
}

double disturb_winds(const TowerInfluenceModel& model, const std::vector<TowerNode>& table,
                     const TowerState& state, const Vec3* points, Vec3* wind, std::size_t count) {
    double clearance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < count; ++i) {
        const DisturbedWind d = disturbed_wind(model, table, state, points[i], wind[i]);
        wind[i] = d.wind;
        clearance = std::min(clearance, d.projection.clearance);
    }
    return clearance;
}

} // namespace yamsc::aero
