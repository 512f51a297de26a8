#include "analysis/hydrodyn_parts.hpp"

namespace yamsc::analysis {

// A row per part as its runtime block lands: strip theory on the members
// (hydro_strip_setup.hpp's strip_setup, strip_theory_block), potential flow for
// PotMod 1 (hydro_potential_setup.hpp's potential_setup, potential_flow_block),
// both sharing one wave field (sea_state_setup.hpp's wave_settings,
// make_wave_field), and the wave elevation at SeaState's WaveElevxi, yi.
const std::vector<HydroPart>& hydrodyn_parts() {
    static const std::vector<HydroPart> parts{};
    return parts;
}

std::string hydrodyn_part_names() {
    std::string names;
    for (const HydroPart& p : hydrodyn_parts())
        names += (names.empty() ? "" : ", ") + std::string(p.name);
    return names.empty() ? "none yet" : names;
}

} // namespace yamsc::analysis
