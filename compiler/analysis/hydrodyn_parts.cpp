#include "analysis/hydrodyn_parts.hpp"

#include "analysis/hydro_potential_setup.hpp"
#include "analysis/hydro_strip_setup.hpp"
#include "diag/errors.hpp"

#include <yamsc/hydro/potential_flow.hpp>
#include <yamsc/hydro/strip_theory.hpp>
#include <yamsc/hydro/wave_elevation.hpp>

namespace yamsc::analysis {

namespace {

template <class Setup> Setup required(std::optional<Setup> s, const diag::Diagnostics& diags) {
    if (!s || diags.has_errors()) throw diag::UserError(diags.render());
    return std::move(*s);
}

/// The members (PotMod 0, or the viscous drag of PropPot members with PotMod 1).
std::shared_ptr<const runtime::LoadBlock> strip(const HydroContext& h) {
    diag::Diagnostics diags;
    runtime::hydro::StripSetup s = required(strip_setup(*h.hydrodyn, h.water, diags), diags);
    s.waves = h.waves;
    s.water = h.water;
    s.origin_at_rest = h.mesh.origin_at_rest;
    s.frame_outputs = h.mesh.frame_outputs;
    s.loads = h.mesh.loads;
    s.output_prefix = h.output_prefix;
    return runtime::hydro::strip_theory_block(std::move(s));
}

/// WAMIT's coefficients for PotMod 1, with the additional matrices.
std::shared_ptr<const runtime::LoadBlock> potential(const HydroContext& h) {
    diag::Diagnostics diags;
    runtime::hydro::PotentialFlowSetup s =
        required(potential_setup(*h.hydrodyn, h.water, diags), diags);
    s.waves = h.waves;
    s.water = h.water;
    s.origin_at_rest = h.mesh.origin_at_rest;
    s.frame_outputs = h.mesh.frame_outputs;
    s.loads = h.mesh.loads;
    s.output_prefix = h.output_prefix + "B1";
    return runtime::hydro::potential_flow_block(std::move(s));
}

/// SeaState's WaveElevxi, WaveElevyi as <prefix>Wave<k>Elev.
std::shared_ptr<const runtime::LoadBlock> elevation(const HydroContext& h) {
    std::vector<runtime::hydro::ElevationPoint> points;
    for (std::size_t k = 0; k < h.sea_state->wave_elev_x.size(); ++k)
        points.push_back({h.sea_state->wave_elev_x[k], h.sea_state->wave_elev_y[k]});
    return runtime::hydro::wave_elevation_block(h.waves, std::move(points), h.output_prefix);
}

} // namespace

const std::vector<HydroPart>& hydrodyn_parts() {
    static const std::vector<HydroPart> parts{
        {"strip theory on the members",
         [](const HydroContext& h) { return !h.hydrodyn->members.empty(); }, strip},
        {"potential flow (PotMod 1)",
         [](const HydroContext& h) {
             return h.hydrodyn->pot_mod == hydrodyn::PotentialFlow::wamit;
         },
         potential},
        {"the wave elevation (SeaState's NWaveElev points)",
         [](const HydroContext& h) {
             return h.sea_state && !h.sea_state->wave_elev_x.empty() &&
                    h.sea_state->wave_elev_x.size() == h.sea_state->wave_elev_y.size();
         },
         elevation},
    };
    return parts;
}

std::string hydrodyn_part_names() {
    std::string names;
    for (const HydroPart& p : hydrodyn_parts())
        names += (names.empty() ? "" : ", ") + std::string(p.name);
    return names;
}

} // namespace yamsc::analysis
