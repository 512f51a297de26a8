#pragma once
// The builders of the load-block kinds (one file each, rotor_table_block.cpp,
// ...), registered in load_blocks.cpp: a model's declaration of the kind, its
// roles bound to names of the view, turned into the runtime's block.
#include "analysis/load_blocks.hpp"
#include "model/model.hpp"

#include <yamsc/aero/blade_element_block.hpp>
#include <yamsc/wind/wind_field.hpp>

#include <memory>

namespace yamsc::analysis {

/// What a builder gets besides the declaration.
struct BlockContext {
    const Loaded& loaded;
    const runtime::ModelView& view;    // the view the block is closed around
    const std::vector<double>& params; // the parameters it is bound to
    const BlockOptions& options;
    /// --wind's field (an InflowWind file), or null: V_wind along ground x.
    std::shared_ptr<const runtime::WindField> wind_field;
};

/// The index of `name` in `names` (the checker has seen it declared).
int index_in(const std::vector<std::string>& names, const std::string& name);

/// The value of parameter `name` in the context.
double parameter(const BlockContext& c, const std::string& name);

std::shared_ptr<const runtime::LoadBlock> build_rotor_table(const model::LoadBlock& decl,
                                                            const BlockContext& c);
/// The blade elements of `decl` bound to the view `v` of `m`: the channels, the
/// blades' and tower's body points, the output prefix and the options'
/// derivative settings; no rotor (aerodyn_input::with_aerodyn_rotor reads it)
/// and no wind field. `yamsc sim` and `yamsc fmu` (the unit's plan) both start here.
aero::BladeElementSetup blade_element_channels(const model::LoadBlock& decl, const model::Model& m,
                                               const runtime::ModelView& v, const BlockOptions& o);
std::shared_ptr<const runtime::LoadBlock> build_blade_elements(const model::LoadBlock& decl,
                                                               const BlockContext& c);
/// MAP++'s lines of --mooring on the platform (mooring_block.cpp).
std::shared_ptr<const runtime::LoadBlock> build_mooring(const model::LoadBlock& decl,
                                                        const BlockContext& c);
/// HydroDyn's loads of --hydro (and --sea-state's waves) on the platform: a
/// block per part of the file (hydrodyn_block.cpp, hydrodyn_parts.hpp).
runtime::LoadBlocks build_hydrodyn(const model::LoadBlock& decl, const BlockContext& c);

} // namespace yamsc::analysis
