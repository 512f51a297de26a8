#pragma once
// AeroDyn's blade elements (`load blade_elements`) inside a unit: what `yamsc fmu`
// resolves at packaging time (the view's channel indices, the blades' and
// tower's body points, the options `yamsc sim` runs the block with), written
// into the glue as text, and the hook that builds the runtime's block from it
// when the unit is instantiated, with AeroDyn's files read from resources/.
//
// The functions below are defined in libyamsc_aerodyn_input.a (the AeroDyn
// reader and its conversion, compiler/aerodyn_input), which a unit with blade
// elements links besides libyamsc_fmi.a; this header keeps their types.
#include "yamsc/fmi/unit.hpp"

#include <yamsc/aero/blade_element_block.hpp>

#include <string>
#include <vector>

namespace yamsc::fmi {

struct BladeElementsPlan {
    /// The AeroDyn primary file, relative to the resources folder (its blade and
    /// airfoil files beside it as the primary file names them).
    std::string aerodyn;
    /// > 0: the BEM's inflow-angle tolerance [rad]; 0: AeroDyn's, as sim runs it.
    double inflow_angle_tolerance = 0;
    /// Channels, body points, output prefix, frozen_wake and difference_step;
    /// its rotor and wind field are left empty (read from `aerodyn`; the wind is
    /// the block's wind input, which the host drives).
    aero::BladeElementSetup setup;
};

/// The plan as text, every number the shortest that reads back exactly.
std::string blade_elements_plan_text(const BladeElementsPlan& plan);

/// The plan of a text blade_elements_plan_text wrote (std::invalid_argument
/// naming the token at fault for any other).
BladeElementsPlan read_blade_elements_plan(const std::string& text);

/// The hook that closes one blade-element block per plan text around a unit's
/// view, tightly coupled, as `yamsc sim` closes it (its discrete states, UA and
/// DBEMT, make GetFMUState refuse). Throws, when called, diag::UserError (a
/// std::runtime_error) for AeroDyn files that cannot be read.
BlockHook blade_elements_hook(std::vector<std::string> plan_texts);

} // namespace yamsc::fmi
