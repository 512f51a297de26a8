#include "analysis/moordyn_mooring.hpp"

#include "diag/read_text.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

namespace yamsc::analysis {
namespace {

using diag::Kind;
using moordyn::Attachment;

// An anchor is on the seabed when its Z is minus the depth to round-off of
// numbers written with a few decimals.
constexpr double seabed_tolerance = 1e-9;

const char* attachment_name(Attachment a) {
    switch (a) {
    case Attachment::fixed:
        return "Fixed";
    case Attachment::coupled:
        return "Vessel";
    case Attachment::free:
        return "Free";
    case Attachment::body:
        return "Body";
    case Attachment::turbine:
        return "Turbine";
    }
    return "";
}

} // namespace

std::optional<std::vector<runtime::mooring::Line>> moordyn_lines(const moordyn::MoorDynInput& input,
                                                                 const MooringEnvironment& env,
                                                                 diag::Diagnostics& diags) {
    int errors = 0;
    auto error = [&](Kind kind, const diag::Location& at, std::string message) {
        ++errors;
        diags.error(kind, at, std::move(message));
    };
    const double g = input.gravity.value_or(env.gravity);
    const double rho = input.water_density.value_or(env.water_density);
    const double depth = input.water_depth.value_or(env.water_depth);
    if (!(depth > 0) || !(rho > 0) || !(g > 0)) {
        error(Kind::InvalidValue,
              input.water_depth ? input.water_depth_at : diag::Location{input.file, 0, 0},
              "mooring: the water depth, water density and gravity must be positive");
        return std::nullopt;
    }
    const diag::Location options_at =
        input.options_at.line > 0 ? input.options_at : diag::Location{input.file, 1, 1};
    diags.warning(Kind::NotSupported, options_at,
                  "MoorDyn's lines run here quasi-static (elastic catenaries with seabed contact, "
                  "as MAP++), not as MoorDyn's lumped-mass dynamics: NumSegs, BA, EI, Cd, Ca, "
                  "CdAx, CaAx, dtM and the seabed's kBot and cBot are not used, and the seabed "
                  "has no friction");
    for (const moordyn::Option& o : input.options)
        if ((o.name == "MU_KT" || o.name == "MU_KA") && std::strtod(o.value.c_str(), nullptr) != 0)
            diags.warning(Kind::NotSupported, o.at,
                          "MoorDyn's seabed friction (mu_kT, mu_kA) acts on its dynamic lines "
                          "only: the quasi-static seabed has no friction");
    for (const auto* rows : {&input.rod_types, &input.bodies, &input.rods})
        for (const moordyn::OtherRow& r : *rows)
            error(Kind::NotSupported, r.at,
                  std::string(rows == &input.rod_types ? "rod types"
                              : rows == &input.bodies  ? "bodies"
                                                       : "rods") +
                      " are not supported: MoorDyn's lines are converted alone ('" + r.name + "')");
    for (const moordyn::Point& p : input.points) {
        const std::string entry = "point " + std::to_string(p.id);
        if (p.attachment != Attachment::fixed && p.attachment != Attachment::coupled)
            error(Kind::NotSupported, p.attachment_at,
                  std::string(attachment_name(p.attachment)) + " " + entry +
                      " is not supported: each line must run from a Fixed point (an anchor) to "
                      "a Vessel or Coupled point (a fairlead on the body), without line networks");
        else if (p.mass != 0 || p.volume != 0)
            error(Kind::NotSupported, p.at,
                  "the mass and volume of " + entry +
                      " are not supported (point masses and buoyancy modules)");
        else if (p.force[0] != 0 || p.force[1] != 0 || p.force[2] != 0)
            error(Kind::NotSupported, p.at,
                  "the forces (FX, FY, FZ) on " + entry + " are not supported");
        else if (p.attachment == Attachment::fixed) {
            const double z = p.on_seabed ? -depth : p.z;
            if (std::abs(z + depth) > seabed_tolerance * depth)
                error(Kind::NotSupported, p.z_at,
                      "anchor " + entry + " is not on the seabed (Z = " + std::to_string(p.z) +
                          ", the water " + std::to_string(depth) +
                          " m deep): the quasi-static line's seabed is at its anchor");
        }
    }
    std::vector<runtime::mooring::Line> lines;
    for (const moordyn::LineRow& row : input.lines) {
        const std::string entry = "line " + std::to_string(row.id);
        if (row.end_a.rod || row.end_b.rod) {
            error(Kind::NotSupported, row.end_a.rod ? row.end_a.at : row.end_b.at,
                  "the end of " + entry + " on a rod is not supported");
            continue;
        }
        const moordyn::Point& a = input.points[row.end_a.number - 1];
        const moordyn::Point& b = input.points[row.end_b.number - 1];
        // MoorDyn's lines run from end A to end B, usually anchor to fairlead; the
        // catenary is the same line either way round.
        const bool a_anchor = a.attachment == Attachment::fixed;
        const moordyn::Point& anchor = a_anchor ? a : b;
        const moordyn::Point& fairlead = a_anchor ? b : a;
        if (anchor.attachment != Attachment::fixed || fairlead.attachment != Attachment::coupled) {
            error(Kind::NotSupported, row.end_a.at,
                  entry + " must run from a Fixed point to a Vessel or Coupled point (it joins " +
                      attachment_name(a.attachment) + " point " + std::to_string(a.id) + " to " +
                      attachment_name(b.attachment) + " point " + std::to_string(b.id) + ")");
            continue;
        }
        const moordyn::LineType* type = nullptr;
        for (const moordyn::LineType& t : input.line_types)
            if (t.name == row.type) type = &t;
        if (!type) {
            error(Kind::UnknownName, row.type_at, "unknown line type '" + row.type + "'");
            continue;
        }
        if (type->stiffness_values > 1) {
            error(Kind::NotSupported, type->at,
                  "the visco-elastic EA of line type '" + type->name + "' is not supported");
            continue;
        }
        runtime::mooring::Line line;
        line.properties.length = row.unstretched_length;
        line.properties.axial_stiffness = type->axial_stiffness;
        // MoorDyn's submerged weight per length (MoorDyn_Line.f90): g (m - rhoW pi d^2 / 4).
        line.properties.weight_in_fluid =
            g * (type->mass_density - rho * M_PI * type->diameter * type->diameter / 4);
        // MoorDyn's seabed pushes back as a spring-damper (kBot, cBot) and has no
        // friction unless mu_kT/mu_kA are set: a frictionless seabed at the anchor.
        line.properties.seabed_friction = 0;
        if (!(line.properties.weight_in_fluid > 0))
            error(Kind::InvalidValue, type->at,
                  "line type '" + type->name + "' floats: its weight in water is not positive");
        line.anchor = {anchor.x, anchor.y, anchor.on_seabed ? -depth : anchor.z};
        line.fairlead = {fairlead.x, fairlead.y, fairlead.z};
        lines.push_back(line);
    }
    if (errors) return std::nullopt;
    return lines;
}

std::optional<std::vector<runtime::mooring::Line>>
read_moordyn_mooring(const std::filesystem::path& file, const MooringEnvironment& env,
                     diag::Diagnostics& diags) {
    const auto text = diag::read_text_file(file.string(), diags);
    if (!text) return std::nullopt;
    const auto input = moordyn::read_moordyn_input(text, diags);
    if (!input) return std::nullopt;
    return moordyn_lines(*input, env, diags);
}

} // namespace yamsc::analysis
