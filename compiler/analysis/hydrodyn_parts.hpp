#pragma once
// The parts one `load hydrodyn` declaration builds from a HydroDyn file and its
// SeaState file, each a load block on the platform's mesh: a table of
// {name, applies, build} (hydrodyn_parts.cpp), so that strip theory (PotMod 0
// members), potential flow (PotMod 1) and the wave elevation each add a row.
#include "analysis/platform_mesh.hpp"
#include "hydrodyn/hydrodyn_input.hpp"
#include "seastate/seastate_input.hpp"

#include <yamsc/hydro/waves.hpp>
#include <yamsc/load_block.hpp>

#include <memory>
#include <string>
#include <vector>

namespace yamsc::analysis {

/// What every part is built from.
struct HydroContext {
    PlatformMesh mesh;
    runtime::hydro::Water water; // depth below the still-water level
    const hydrodyn::Input* hydrodyn = nullptr;
    const seastate::Input* sea_state = nullptr; // null: still water
    /// The one wave field every part samples (null: still water in `water`).
    std::shared_ptr<const runtime::hydro::WaveField> waves;
    std::string output_prefix; // the block's outputs <prefix>...
};

struct HydroPart {
    const char* name;
    bool (*applies)(const HydroContext&);
    std::shared_ptr<const runtime::LoadBlock> (*build)(const HydroContext&);
};

const std::vector<HydroPart>& hydrodyn_parts();
/// The parts' names, for a message.
std::string hydrodyn_part_names();

} // namespace yamsc::analysis
