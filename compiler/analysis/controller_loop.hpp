#pragma once
// `sim --controller LIB [--controller-input FILE]`: a Bladed-style DISCON
// library in the loop (runtime/include/yamsc/discon.hpp), called at every
// output step with the model's measurements; its collective pitch and
// generator torque demands are held until the next call. The model provides
// (by name) the inputs pitch [rad] and gen_torque [N m], the outputs
// rotor_speed [rad/s] and GenSpeed [rpm], and optionally Azimuth [deg],
// GenPwr [kW] and the input V_wind. The controller's output name is
// `output_root`.SrvD, as OpenFAST names it (ROSCO writes `output_root`.RO.dbg).
#include <yamsc/model_view.hpp>
#include <yamsc/simulation.hpp>

#include <string>

namespace yamsc::driver {

runtime::SimulationResult simulate_with_controller(const runtime::ModelView& view,
                                                   const runtime::SimulationOptions& options,
                                                   const std::string& library,
                                                   const std::string& input_file,
                                                   const std::string& output_root = "yamsc");

/// The root of a run's files: `output` without its extension ("yamsc" when empty).
std::string output_root_of(const std::string& output);

} // namespace yamsc::driver
