// Lumped rigid rotor and tower of an ElastoDyn deck (see rotor.hpp).
#include "openfast/rotor.hpp"

#include "driver/files.hpp"
#include "elastodyn/file.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::openfast {

using driver::read_source;

namespace {

constexpr double pi = 3.14159265358979323846;

/// (position along the span from the root [m], lumped mass [kg]) of each element.
using Elements = std::vector<std::pair<double, double>>;

/// ElastoDyn's elements of a blade or tower file: `count_key` rows of the table whose
/// first column is `fraction`, mass density column `density` times `factor_key`.
std::optional<Elements> lumped_elements(const std::string& path, const char* count_key,
                                        const char* fraction, const char* density,
                                        const char* factor_key, double length, int nodes,
                                        diag::Diagnostics& diags) {
    auto source = read_source(path, diags);
    if (!source) return std::nullopt;
    const elastodyn::ElastoDynFile f(source);
    auto rows = f.get_int(count_key, diags);
    auto factor = f.get_double(factor_key, diags);
    if (!rows || !factor) return std::nullopt;
    auto table = f.get_table(fraction, *rows, diags);
    if (!table) return std::nullopt;
    const int column = table->column(density);
    if (column < 0 || table->rows.size() < 2) {
        diags.error(diag::Kind::MissingProperty, {source, table->header_line, 1},
                    std::string("the table has no column '") + density + "'");
        return std::nullopt;
    }
    auto density_at = [&](double s) {
        const auto& r = table->rows;
        if (s <= r.front()[0]) return r.front()[static_cast<std::size_t>(column)];
        for (std::size_t i = 1; i < r.size(); ++i)
            if (s <= r[i][0]) {
                const double w = (s - r[i - 1][0]) / (r[i][0] - r[i - 1][0]);
                return (1 - w) * r[i - 1][static_cast<std::size_t>(column)] +
                       w * r[i][static_cast<std::size_t>(column)];
            }
        return r.back()[static_cast<std::size_t>(column)];
    };
    Elements e;
    const double dr = length / nodes;
    for (int i = 0; i < nodes; ++i) {
        const double r = (i + 0.5) * dr;
        e.emplace_back(r, *factor * density_at(r / length) * dr);
    }
    return e;
}

/// Accumulates point masses: mass, first moment and inertia about the origin.
struct Accumulator {
    double mass = 0;
    std::array<double, 3> first{};
    std::array<double, 6> inertia{}; // Ixx Iyy Izz Ixy Iyz Ixz about the origin

    void add(double m, const std::array<double, 3>& p) {
        mass += m;
        for (int i = 0; i < 3; ++i)
            first[static_cast<std::size_t>(i)] += m * p[static_cast<std::size_t>(i)];
        const double x = p[0], y = p[1], z = p[2];
        inertia[0] += m * (y * y + z * z);
        inertia[1] += m * (x * x + z * z);
        inertia[2] += m * (x * x + y * y);
        inertia[3] -= m * x * y;
        inertia[4] -= m * y * z;
        inertia[5] -= m * x * z;
    }

    /// About the centre of mass, with rounding noise of symmetric layouts removed.
    RigidProperties about_cm() const {
        RigidProperties r;
        r.mass = mass;
        if (mass <= 0) return r;
        for (int i = 0; i < 3; ++i)
            r.cm[static_cast<std::size_t>(i)] = first[static_cast<std::size_t>(i)] / mass;
        const double x = r.cm[0], y = r.cm[1], z = r.cm[2];
        r.inertia = inertia;
        r.inertia[0] -= mass * (y * y + z * z);
        r.inertia[1] -= mass * (x * x + z * z);
        r.inertia[2] -= mass * (x * x + y * y);
        r.inertia[3] += mass * x * y;
        r.inertia[4] += mass * y * z;
        r.inertia[5] += mass * x * z;
        const double scale =
            std::max({std::abs(r.inertia[0]), std::abs(r.inertia[1]), std::abs(r.inertia[2]), 1.0});
        for (std::size_t i = 3; i < 6; ++i)
            if (std::abs(r.inertia[i]) < 1e-9 * scale) r.inertia[i] = 0;
        if (std::abs(r.inertia[1] - r.inertia[2]) < 1e-9 * scale)
            r.inertia[1] = r.inertia[2] = 0.5 * (r.inertia[1] + r.inertia[2]);
        const double length = std::sqrt(x * x + y * y + z * z) + 1.0;
        for (double& c : r.cm)
            if (std::abs(c) < 1e-12 * length) c = 0;
        return r;
    }
};

/// Blade k's (0-based) elements, from its root along the blade; nullopt after errors.
std::optional<Elements> blade_elements(const openfast::OpenFastDeck& deck, int k,
                                       diag::Diagnostics& diags) {
    const double length = deck["TipRad"] - deck["HubRad"];
    if (!(length > 0)) {
        diags.error(diag::Kind::InvalidValue, {deck.ed, 0, 0},
                    "TipRad must be larger than HubRad (the blade length is their difference)");
        return std::nullopt;
    }
    return lumped_elements(deck.blade_files[static_cast<std::size_t>(k)], "NBlInpSt", "BlFract",
                           "BMassDen", "AdjBlMs", length, deck.blade_nodes, diags);
}

} // namespace

std::optional<RigidProperties> rigid_blade(const openfast::OpenFastDeck& deck, int k,
                                           diag::Diagnostics& diags) {
    auto elements = blade_elements(deck, k - 1, diags);
    if (!elements) return std::nullopt;
    Accumulator blade;
    for (const auto& [s, m] : *elements) blade.add(m, {0, 0, s});
    blade.add(deck["TipMass" + std::to_string(k)], {0, 0, deck["TipRad"] - deck["HubRad"]});
    return blade.about_cm();
}

std::optional<RigidProperties> rigid_rotor(const openfast::OpenFastDeck& deck,
                                           diag::Diagnostics& diags) {
    Accumulator rotor;
    rotor.add(deck["HubMass"], {deck["HubCM"], 0, 0});
    rotor.inertia[0] += deck["HubIner"]; // about the shaft; ElastoDyn's hub has no other inertia
    for (int k = 0; k < deck.blades; ++k) {
        auto elements = blade_elements(deck, k, diags);
        if (!elements) return std::nullopt;
        const std::string n = std::to_string(k + 1);
        const double cone = deck["PreCone" + n] * pi / 180;
        const double azimuth = 2 * pi * k / deck.blades;
        auto at = [&](double r) -> std::array<double, 3> {
            // Along the coned blade axis, then turned about the shaft to the blade's azimuth.
            const double axial = r * std::sin(cone), radial = r * std::cos(cone);
            return {axial, -std::sin(azimuth) * radial, std::cos(azimuth) * radial};
        };
        for (const auto& [s, m] : *elements) rotor.add(m, at(deck["HubRad"] + s));
        rotor.add(deck["TipMass" + n], at(deck["TipRad"]));
    }
    return rotor.about_cm();
}

std::optional<RigidProperties> rigid_tower(const openfast::OpenFastDeck& deck,
                                           diag::Diagnostics& diags) {
    const double length = deck["TowerHt"] - deck["TowerBsHt"];
    if (!(length > 0)) {
        diags.error(diag::Kind::InvalidValue, {deck.ed, 0, 0},
                    "TowerHt must be larger than TowerBsHt (the tower length is their difference)");
        return std::nullopt;
    }
    auto elements = lumped_elements(deck.tower_file, "NTwInpSt", "HtFract", "TMassDen", "AdjTwMa",
                                    length, deck.tower_nodes, diags);
    if (!elements) return std::nullopt;
    Accumulator tower;
    for (const auto& [z, m] : *elements) tower.add(m, {0, 0, z});
    return tower.about_cm();
}

} // namespace yamsc::openfast
