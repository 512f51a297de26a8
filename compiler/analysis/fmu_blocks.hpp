#pragma once
// The load blocks a unit closes when it is instantiated (yamsc/fmi/blocks.hpp):
// what `yamsc fmu` resolves from the model's `load` declarations at packaging
// time (the channels and parameters each binds, its data file under
// resources/), written into the unit's glue as a yamsc::fmi::BlockPlan.
#include "analysis/load_blocks.hpp"
#include "model/model.hpp"

#include <string>
#include <vector>

namespace yamsc::analysis {

/// What a unit carries for its blocks.
struct UnitBlocks {
    /// C++ statements, in the glue's settings function, that set `s.close_blocks`
    /// ("" without blocks).
    std::string source;
    /// The data files to copy, and their names under resources/ (same order).
    std::vector<std::string> files, names;
    bool blade_elements = false; // the unit links the AeroDyn reader
};

/// The blocks `b` supplies for the model `m` (its base view `base`, the one
/// the unit's hook closes them around; `param_names`: its parameters). Rotor
/// tables: each table file by its name. Blade elements: the AeroDyn primary
/// file and every file it reads, under resources/aerodyn/ at their paths
/// relative to the folder that holds them all (so the primary file's relative
/// names still resolve), and the plan (yamsc/fmi/blade_elements.hpp) as text.
UnitBlocks unit_blocks(const model::Model& m, const runtime::ModelView& base,
                       const std::vector<std::string>& param_names, const BlockOptions& b);

} // namespace yamsc::analysis
