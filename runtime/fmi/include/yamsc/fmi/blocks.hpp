#pragma once
// Load blocks inside a unit: what `yamsc fmu` resolves at packaging time from
// the model's `load` declarations (channel names, the parameters a block reads,
// its data file copied under resources/), and the hook that builds the
// runtime's blocks from it when the unit is instantiated (UnitSettings::close_blocks).
// The blocks are the runtime's own (rotor_table_block, close_blocks): the same
// code `yamsc sim` closes around the model, tightly coupled (every stage of a
// co-simulation step, and a model exchange host's own integrator, see the
// loads at its own state).
#include "yamsc/fmi/unit.hpp"

#include <string>
#include <vector>

namespace yamsc::fmi {

/// `load rotor_table NAME { ... }`: the quasi-steady rotor block (yamsc/rotor_aero.hpp).
struct RotorTablePlan {
    std::string name;  // the declaration's name (its outputs are NAME_thrust, ...)
    std::string table; // the Cp/Ct/Cq file, relative to the resources folder
    int radius_parameter = -1, density_parameter = -1; // indices of the model's parameters
    // The model's channels the block binds (runtime::bind_rotor_aero); pitch may be empty.
    std::string wind, pitch, thrust, torque, speed, hub_velocity;
};

/// Every block of a unit, in the order they are closed.
struct BlockPlan {
    std::vector<RotorTablePlan> rotor_tables;
};

/// The hook that closes the plan's blocks around a unit's view (empty plan:
/// an empty hook). Throws, when called, std::invalid_argument or
/// std::runtime_error naming the block and the file or channel at fault.
BlockHook block_hook(BlockPlan plan);

} // namespace yamsc::fmi
