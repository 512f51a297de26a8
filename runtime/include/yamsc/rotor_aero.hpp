#pragma once
// Quasi-steady rotor aerodynamics as a load block around a model: thrust along
// the shaft and torque about it from a performance table (Cp/Ct/Cq over
// tip-speed ratio and pitch) and the relative wind at the hub,
//   V_rel = V - v_hub,   lambda = Omega R / V_rel,
//   T = 1/2 rho pi R^2 V_rel^2 Ct(lambda, beta),  Q = 1/2 rho pi R^3 V_rel^2 Cq(lambda, beta).
// The model declares the loads as inputs (force and torque on the rotor) and
// the hub's velocity along the shaft and the rotor speed as outputs; the
// wrapped view feeds the loads back, so the tower sees its aerodynamic damping
// (v_hub) and the rotor its speed feedback (lambda). It is a LoadBlock
// (load_block.hpp) without states.
#include "yamsc/load_block.hpp"
#include "yamsc/model_view.hpp"
#include "yamsc/performance_table.hpp"

#include <memory>
#include <string>
#include <vector>

namespace yamsc::runtime {

struct RotorAero {
    PerformanceTable table;
    double radius = 0;  // R [m]
    double density = 0; // rho [kg/m^3]
    // Channels of the model's u: the hub-height wind [m/s], the collective
    // pitch [rad] (-1: always 0), the thrust [N] and aerodynamic torque [N m]
    // the block adds to whatever the caller gives.
    int wind_input = -1, pitch_input = -1, thrust_input = -1, torque_input = -1;
    // Outputs of the model: rotor speed [rad/s] and the hub's velocity along
    // the shaft, downwind positive [m/s].
    int speed_output = -1, hub_velocity_output = -1;
    std::string name = "aero"; // its outputs are NAME_thrust, NAME_torque_out, ...
};

/// Loads and their exact partial derivatives in V_rel, Omega and pitch [rad].
struct RotorLoads {
    double v_rel = 0, tsr = 0, pitch_deg = 0;
    double cp = 0, ct = 0, cq = 0;
    double thrust = 0, torque = 0, power = 0;
    double dT_dV = 0, dT_dOmega = 0, dT_dpitch = 0; // dV: relative wind
    double dQ_dV = 0, dQ_dOmega = 0, dQ_dpitch = 0;
};

/// Throws std::invalid_argument when V_rel <= 0 (no wind through the rotor).
RotorLoads rotor_loads(const RotorAero& aero, double v_rel, double omega, double pitch_rad);

/// The block's channels by the names the model uses; throws std::invalid_argument
/// naming what is missing. Pitch may be empty (0 rad).
RotorAero bind_rotor_aero(const ModelView& view, PerformanceTable table, double radius,
                          double density, const std::string& wind, const std::string& pitch,
                          const std::string& thrust, const std::string& torque,
                          const std::string& speed, const std::string& hub_velocity);

/// The block: it reads the rotor speed and hub velocity outputs and the wind
/// and pitch inputs, adds thrust and torque to their inputs; its outputs are
/// NAME_thrust [N], NAME_torque_out [N m], NAME_power [W], NAME_tsr,
/// NAME_v_rel [m/s], NAME_cp, NAME_ct; its derivatives are exact (the table's
/// partials).
std::shared_ptr<const LoadBlock> rotor_table_block(RotorAero aero);

/// `base` with the block closed around it (close_blocks).
ModelView with_rotor_aero(const ModelView& base, const RotorAero& aero);

} // namespace yamsc::runtime
