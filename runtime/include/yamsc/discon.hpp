#pragma once
// A Bladed-style controller library (DISCON, as ROSCO and the NREL 5-MW
// baseline controller export it) called at the controller step with the swap
// records ROSCO reads (Bladed User's Guide, appendix A; ROSCO's ReadAvrSWAP):
//   1 status (0 first call, 1 running, -1 last), 2 time [s], 3 step [s],
//   4/33/34 blade pitch [rad], 14/15 mechanical/electrical power [W],
//   20 generator speed [rad/s], 21 rotor speed [rad/s], 23 generator torque
//   [N m], 27 hub wind speed [m/s], 49/50/51 lengths of the message, input
//   and output names, 53/54 tower-top fore-aft/side-side acceleration
//   [m/s^2], 60 rotor azimuth [rad], 61 number of blades, 129 size of the array;
// back: 45 collective pitch demand [rad], 47 generator torque demand [N m].
#include <memory>
#include <string>

namespace yamsc::runtime {

struct ControllerMeasurements {
    double time = 0, step = 0;
    double pitch = 0;                                  // [rad], every blade
    double mech_power = 0, power = 0;                  // [W]
    double gen_speed = 0, rotor_speed = 0;             // [rad/s]
    double gen_torque = 0;                             // [N m]
    double wind = 0;                                   // hub-height [m/s]
    double tower_top_fa_acc = 0, tower_top_ss_acc = 0; // [m/s^2]
    double azimuth = 0;                                // [rad]
};

struct ControllerDemands {
    double pitch = 0;      // collective [rad]
    double gen_torque = 0; // [N m]
};

class DisconController {
public:
    /// Loads `library` (a path; dlopen) and its DISCON; throws std::runtime_error.
    /// `output_name` is the avcOUTNAME argument, the simulation's root name with
    /// an extension as OpenFAST's ServoDyn passes it (`case.SrvD`): ROSCO strips
    /// the extension and writes its debug channels to `case.RO.dbg`.
    DisconController(const std::string& library, std::string input_file,
                     std::string output_name = "yamsc.SrvD");
    ~DisconController();
    DisconController(const DisconController&) = delete;
    DisconController& operator=(const DisconController&) = delete;

    /// One call: status 0 on the first, 1 after; `last` for the final call.
    /// Throws std::runtime_error with the controller's message when it fails.
    ControllerDemands call(const ControllerMeasurements& m, bool last = false);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace yamsc::runtime
