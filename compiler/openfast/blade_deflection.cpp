// ElastoDyn's initial blade deflections (see blade_deflection.hpp).
#include "openfast/blade_deflection.hpp"

#include "beam/elastodyn.hpp"
#include "beam/make_sid.hpp"
#include "driver/files.hpp"

#include <cmath>

namespace yamsc::openfast {

using driver::read_source;

namespace {

/// A station property, linear in the span fraction (as ElastoDyn interpolates).
double mass_at(const beam::Beam& b, double s) {
    const auto& st = b.stations;
    if (s <= st.front().s) return st.front().mass_per_length;
    for (std::size_t i = 1; i < st.size(); ++i)
        if (s <= st[i].s) {
            const double t = (s - st[i - 1].s) / (st[i].s - st[i - 1].s);
            return (1 - t) * st[i - 1].mass_per_length + t * st[i].mass_per_length;
        }
    return st.back().mass_per_length;
}

/// See BladeTipShapes::spin_inertia and ::shortening_coriolis. The SID's nodes 1..N are
/// the element centres; its shapes are in the pitched blade axes, turned here into the
/// coned axes (x out of plane, y in plane: the blade's direction of rotation is -y).
void second_order_inertia(const beam::Beam& b, const sid::Sid& sid, double hub_radius, double cone,
                          double pitch, BladeTipShapes& t) {
    auto& c = t.spin_inertia;
    auto& d = t.shortening_coriolis;
    c = {};
    d = {};
    const double dr = b.length / b.elements, sb = std::sin(cone), cb = std::cos(cone);
    const double sp = std::sin(pitch), cp = std::cos(pitch);
    for (int e = 0; e < b.elements; ++e) {
        const double r = (e + 0.5) * dr;
        const double m = mass_at(b, r / b.length) * dr;
        const sid::Node& n = sid.nodes[static_cast<std::size_t>(e + 1)];
        std::array<double, 3> x{}, y{}; // coned-frame shape components per DOF
        for (std::size_t j = 0; j < 3; ++j) {
            const double px = n.phi.at0(0, static_cast<int>(j)),
                         py = n.phi.at0(1, static_cast<int>(j));
            x[j] = cp * px + sp * py;
            y[j] = -sp * px + cp * py;
        }
        for (std::size_t j = 0; j < 3; ++j)
            for (std::size_t k = 0; k < 3; ++k) {
                // AxRedBld_jk: the shortening along the blade, -phi1_z.
                const double axred = -n.phi.at1(2, static_cast<int>(j), static_cast<int>(k));
                c[j][k] +=
                    m * (y[j] * y[k] + sb * sb * x[j] * x[k] - cb * cb * (hub_radius + r) * axred);
                for (std::size_t i = 0; i < 3; ++i) d[i][j][k] += m * cb * y[i] * axred;
            }
    }
}

} // namespace

std::optional<std::vector<BladeTipShapes>> blade_tip_shapes(const openfast::OpenFastDeck& deck,
                                                            diag::Diagnostics& diags) {
    std::vector<BladeTipShapes> out;
    for (const std::string& path : deck.blade_files) {
        auto source = read_source(path, diags);
        if (!source) return std::nullopt;
        auto blade = beam::read_elastodyn_blade(source, deck["TipRad"] - deck["HubRad"],
                                                {"flap1", "edge1", "flap2"}, diags);
        if (!blade) return std::nullopt;
        blade->elements = deck.blade_nodes;
        const sid::Sid sid = beam::make_sid(*blade);
        const sid::Node& tip = sid.nodes.back();
        BladeTipShapes t;
        for (int a = 0; a < 2; ++a) {
            t.flap1[static_cast<std::size_t>(a)] = tip.phi.at0(a, 0);
            t.edge1[static_cast<std::size_t>(a)] = tip.phi.at0(a, 1);
            t.flap2[static_cast<std::size_t>(a)] = tip.phi.at0(a, 2);
        }
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                t.axial[static_cast<std::size_t>(j)][static_cast<std::size_t>(k)] =
                    tip.phi.at1(2, j, k);
        const int k = static_cast<int>(out.size()) + 1;
        const double deg = std::acos(-1.0) / 180;
        second_order_inertia(*blade, sid, deck["HubRad"], deck["PreCone" + std::to_string(k)] * deg,
                             deck["BlPitch" + std::to_string(k)] * deg, t);
        out.push_back(t);
    }
    return out;
}

namespace {

bool zero(double v) {
    return std::fabs(v) < 1e-12;
}

} // namespace

BladeInitial initial_blade_deflection(const BladeTipShapes& tip, double pitch, double oop,
                                      double ip, bool flap1_on, bool flap2_on, bool edge_on) {
    BladeInitial r;
    const double c = std::cos(pitch), s = std::sin(pitch);
    // Coned-frame tip deflection per unit DOF (ElastoDyn's matrix A, columns flap, edge).
    auto coned = [&](const std::array<double, 2>& v) {
        return std::array<double, 2>{v[0] * c + v[1] * s, -v[0] * s + v[1] * c};
    };
    const auto e = coned(tip.edge1);
    if (!flap1_on && !flap2_on) {
        if (oop != 0 || ip != 0)
            r.warning = "without flap DOFs ElastoDyn ignores the initial tip deflections";
        return r;
    }
    const auto f = coned(flap1_on ? tip.flap1 : tip.flap2);
    double& flap = flap1_on ? r.flap1 : r.flap2;
    const double det = f[0] * e[1] - e[0] * f[1];
    if (edge_on && !zero(det)) {
        flap = (oop * e[1] - e[0] * ip) / det;
        r.edge1 = (f[0] * ip - oop * f[1]) / det;
    } else if (!edge_on) {
        // ElastoDyn: the flap value that minimises the squared residuals.
        const double n = f[0] * f[0] + f[1] * f[1];
        if (!zero(n)) flap = (f[0] * oop + f[1] * ip) / n;
        const double residual = std::hypot(f[0] * flap - oop, f[1] * flap - ip);
        if (!zero(residual))
            r.warning = "ElastoDyn approximates the initial tip deflection with the flap DOF "
                        "alone (least squares)";
    } else {
        r.warning = "the flap and edge tip shapes are parallel: ElastoDyn ignores the initial "
                    "tip deflections";
    }
    return r;
}

} // namespace yamsc::openfast
