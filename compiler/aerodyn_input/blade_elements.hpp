#pragma once
// AeroDyn's blade elements on a model's meshes: the one setup `yamsc sim` (the
// blade_elements load block, analysis/blade_elements_block.cpp) and an FMI unit
// (yamsc/fmi/blade_elements.hpp) build the runtime's block from.
#include <yamsc/aero/blade_element_block.hpp>

#include <filesystem>
#include <iosfwd>

namespace yamsc::aerodyn_input {

/// `s` (channels, output prefix and derivative settings already set) with its
/// rotor read from the AeroDyn primary file `aerodyn` for as many blades as
/// s.channels has; `inflow_angle_tolerance` > 0 replaces AeroDyn's (1e-6 rad).
/// Errors: diag::UserError with the located diagnostics; warnings go to `warnings`.
aero::BladeElementSetup with_aerodyn_rotor(aero::BladeElementSetup s,
                                           const std::filesystem::path& aerodyn,
                                           double inflow_angle_tolerance, std::ostream& warnings);

} // namespace yamsc::aerodyn_input
