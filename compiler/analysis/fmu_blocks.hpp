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

/// C++ statements, in the glue's settings function, that set `s.close_blocks`
/// for the blocks `b` supplies ("" when none). `resource_names`: each block
/// file's name under resources/ (block_files(b)'s order). Throws
/// diag::UsageError for a kind a unit cannot carry yet (blade elements).
std::string block_plan_source(const model::Model& m, const std::vector<std::string>& param_names,
                              const BlockOptions& b,
                              const std::vector<std::string>& resource_names);

} // namespace yamsc::analysis
