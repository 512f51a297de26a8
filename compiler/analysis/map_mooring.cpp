#include "analysis/map_mooring.hpp"

#include "diag/read_text.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace yamsc::analysis {
namespace {

using diag::Kind;

// MAP++ computes a line's displaced area with this value of pi
// (mapinit.c, initialize_cable_library_variables); its weights in water
// follow it, so ours do (2e-10 relative to the OC3 line's weight).
constexpr double map_pi = 3.14159264;

// REPEAT copies a node rotated by -angle about z and writes the copy's
// coordinates back as text with four decimals ("%1.4f") before reading them
// again: the copies' positions are those rounded numbers.
double as_map_writes_it(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%1.4f", value);
    return std::strtod(text, nullptr);
}

bool same_label(const std::string& a, const std::string& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(a[i])) !=
            std::toupper(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

struct PlacedNode {
    const map::Node* node = nullptr;
    runtime::mooring::Vec3 position{};
};

std::vector<PlacedNode> placed_nodes(const map::MapInput& input, double depth) {
    std::vector<PlacedNode> placed;
    const std::size_t copies = input.repeat_angles.size() + 1;
    for (std::size_t copy = 0; copy < copies; ++copy) {
        const double angle = copy == 0 ? 0 : input.repeat_angles[copy - 1] * M_PI / 180;
        for (const map::Node& n : input.nodes) {
            const double z = n.z.depth ? -depth : n.z.value;
            runtime::mooring::Vec3 p{n.x.value, n.y.value, z};
            if (copy > 0) {
                const double c = std::cos(angle), s = std::sin(angle);
                p = {as_map_writes_it(n.x.value * c + n.y.value * s),
                     as_map_writes_it(-n.x.value * s + n.y.value * c), z};
            }
            placed.push_back({&n, p});
        }
    }
    return placed;
}

} // namespace

std::optional<std::vector<runtime::mooring::Line>>
mooring_lines(const map::MapInput& input, const MooringEnvironment& env, diag::Diagnostics& diags) {
    int errors = 0;
    auto error = [&](Kind kind, const diag::Location& at, std::string message) {
        ++errors;
        diags.error(kind, at, std::move(message));
    };
    if (!(env.water_depth > 0) || !(env.water_density > 0) || !(env.gravity > 0)) {
        error(Kind::InvalidValue, {input.file, 0, 0},
              "mooring: the water depth, water density and gravity must be positive");
        return std::nullopt;
    }
    for (const map::SolverOption& o : input.options) {
        if (o.name != "REF_POSITION") continue;
        for (const std::string& v : o.values)
            if (std::strtod(v.c_str(), nullptr) != 0)
                error(Kind::NotSupported, o.at,
                      "a REF_POSITION other than the body's reference point is not converted");
    }
    for (const map::Node& n : input.nodes) {
        if (n.kind == map::NodeKind::connect)
            error(Kind::NotSupported, n.at,
                  "Connect nodes (lines joined into a network) are not supported: each line must "
                  "run from a Fix node to a Vessel node");
        if (n.kind != map::NodeKind::connect && (n.mass.value != 0 || n.buoyancy.value != 0))
            error(Kind::NotSupported, n.at,
                  "point masses and buoyancy modules on a node are not supported");
    }
    const std::vector<PlacedNode> nodes = placed_nodes(input, env.water_depth);
    const std::size_t per_copy = input.nodes.size();
    std::vector<runtime::mooring::Line> lines;
    for (std::size_t copy = 0; copy <= input.repeat_angles.size(); ++copy) {
        for (const map::LineRow& row : input.lines) {
            const PlacedNode& anchor = nodes[copy * per_copy + row.anchor_node - 1];
            const PlacedNode& fairlead = nodes[copy * per_copy + row.fairlead_node - 1];
            if (anchor.node->kind != map::NodeKind::fix) {
                error(Kind::NotSupported, row.anchor_at,
                      "a line's NodeAnch must be a Fix node (an anchor)");
                continue;
            }
            if (fairlead.node->kind != map::NodeKind::vessel) {
                error(Kind::NotSupported, row.fairlead_at,
                      "a line's NodeFair must be a Vessel node (a fairlead on the body)");
                continue;
            }
            const map::LineType* type = nullptr;
            for (const map::LineType& t : input.line_types)
                if (same_label(t.label, row.type)) type = &t;
            if (!type) {
                error(Kind::UnknownName, row.type_at, "unknown line type '" + row.type + "'");
                continue;
            }
            const double radius = type->diameter / 2;
            runtime::mooring::Line line;
            line.properties.length = row.unstretched_length;
            line.properties.axial_stiffness = type->axial_stiffness;
            line.properties.weight_in_fluid =
                env.gravity * (type->mass_density - map_pi * radius * radius * env.water_density);
            line.properties.seabed_friction = type->seabed_friction;
            for (const std::string& flag : row.flags) {
                if (same_label(flag, "OMIT_CONTACT")) line.properties.seabed_friction = -1;
                if (same_label(flag, "LINEAR_SPRING"))
                    error(Kind::NotSupported, row.at, "LINEAR_SPRING lines are not supported");
            }
            if (!(line.properties.weight_in_fluid > 0))
                error(Kind::InvalidValue, type->at,
                      "line type '" + type->label +
                          "' floats: its weight in water is not positive");
            line.anchor = anchor.position;
            line.fairlead = fairlead.position;
            lines.push_back(line);
        }
    }
    if (errors) return std::nullopt;
    return lines;
}

std::optional<std::vector<runtime::mooring::Line>>
read_map_mooring(const std::filesystem::path& file, const MooringEnvironment& env,
                 diag::Diagnostics& diags) {
    const auto text = diag::read_text_file(file.string(), diags);
    if (!text) return std::nullopt;
    const auto input = map::read_map_input(text, diags);
    if (!input) return std::nullopt;
    return mooring_lines(*input, env, diags);
}

} // namespace yamsc::analysis
