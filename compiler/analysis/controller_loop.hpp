#pragma once
// `sim --controller LIB [--controller-input FILE]`: a Bladed-style DISCON
// library in the loop (runtime/include/yamsc/discon.hpp), called at every
// output step with the model's measurements; its collective pitch and
// generator torque demands are held until the next call. The model provides
// (by name) the inputs pitch [rad] and gen_torque [N m], the outputs
// rotor_speed [rad/s] and GenSpeed [rpm], and optionally Azimuth [deg],
// GenPwr [kW], YawBrTAxp and YawBrTAyp [m/s^2] (the tower-top accelerations,
// records 53 and 54; 0 without them) and the input V_wind. The controller's output name is
// `output_root`.SrvD, as OpenFAST names it (ROSCO writes `output_root`.RO.dbg).
// The controller measures the actuators' outputs (the blade pitch and the
// generator torque applied), as it would on a turbine.
#include "analysis/loaded_model.hpp"

#include <yamsc/model_view.hpp>
#include <yamsc/simulation.hpp>

#include <string>

namespace yamsc::analysis {

/// The actuators between the controller's demands and the model's inputs:
/// first-order lags with these time constants [s], or ideal (0: the demand
/// acts at once). A model chooses them with the parameters
/// `pitch_actuator_tau` and `torque_actuator_tau` (absent: ideal).
struct Actuators {
    double pitch_tau = 0, torque_tau = 0;
};

/// The actuators of a loaded model (its parameters as bound).
Actuators actuators_of(const Loaded& l);

/// The input of a first-order actuator `seconds` after it stood at `from`,
/// with the demand `to` held since (exact for a held demand).
double actuator_lag(double from, double to, double seconds, double tau);

runtime::SimulationResult
simulate_with_controller(const runtime::ModelView& view, const runtime::SimulationOptions& options,
                         const std::string& library, const std::string& input_file,
                         const std::string& output_root = "yamsc", const Actuators& actuators = {});

/// The root of a run's files: `output` without its extension ("yamsc" when empty).
std::string output_root_of(const std::string& output);

} // namespace yamsc::analysis
