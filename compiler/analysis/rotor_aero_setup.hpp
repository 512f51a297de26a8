#pragma once
// `sim`/`lin`/`trim --aero TABLE` and `--wind SPEC`: the runtime's quasi-steady
// rotor block (yamsc/rotor_aero.hpp) closed around a loaded model, and the
// hub-height wind driving its input. The block finds its channels by name
// (docs/cli.md): parameters rotor_radius and air_density, inputs V_wind,
// pitch (optional), thrust and aero_torque, outputs rotor_speed and
// hub_shaft_velocity.
#include "analysis/loaded_model.hpp"

#include <yamsc/integration.hpp>
#include <yamsc/model_view.hpp>

#include <string>
#include <vector>

namespace yamsc::analysis {

/// The model's view with the rotor block closed around it (UserError naming
/// what the model lacks).
runtime::ModelView close_rotor_aero(const Loaded& l, const std::string& table_path);

/// The index of the wind input V_wind in `v` (UserError without one).
int wind_input_index(const runtime::ModelView& v);

/// Inputs `u` with V_wind following --wind (steady, step or file).
runtime::InputFunction wind_inputs(const runtime::ModelView& v, std::vector<double> u,
                                   const std::string& spec);

/// The wind at t = 0 of --wind, written into u's V_wind (for lin and trim).
void set_wind_at_start(const runtime::ModelView& v, std::vector<double>& u,
                       const std::string& spec);

} // namespace yamsc::analysis
