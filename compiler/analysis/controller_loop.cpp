#include "analysis/controller_loop.hpp"

#include "diag/errors.hpp"

#include <yamsc/discon.hpp>
#include <yamsc/integration.hpp>
#include <yamsc/stepper.hpp>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yamsc::analysis {
namespace {

constexpr double pi = 3.14159265358979323846;

int find(const std::vector<std::string>& names, const std::string& name, bool required,
         const char* what) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<int>(i);
    if (required)
        throw diag::UserError(std::string("--controller: the model has no ") + what + " '" + name +
                              "'");
    return -1;
}

} // namespace

Actuators actuators_of(const Loaded& l) {
    auto tau = [&](const char* name) {
        const int i = l.library->param_index(name);
        if (i < 0) return 0.0;
        const double value = l.params[static_cast<std::size_t>(i)];
        if (!(value >= 0) || !std::isfinite(value))
            throw diag::UserError(std::string("the actuator time constant ") + name +
                                  " must be 0 (ideal) or positive [s]");
        return value;
    };
    return {tau("pitch_actuator_tau"), tau("torque_actuator_tau")};
}

double actuator_lag(double from, double to, double seconds, double tau) {
    return tau > 0 ? to + (from - to) * std::exp(-seconds / tau) : to;
}

std::string output_root_of(const std::string& output) {
    if (output.empty()) return "yamsc";
    const auto slash = output.find_last_of('/');
    const auto dot = output.find_last_of('.');
    return dot != std::string::npos && (slash == std::string::npos || dot > slash + 1)
               ? output.substr(0, dot)
               : output;
}

runtime::SimulationResult
simulate_with_controller(const runtime::ModelView& v, const runtime::SimulationOptions& options,
                         const std::string& library, const std::string& input_file,
                         const std::string& output_root, const Actuators& actuators) {
    const int pitch = find(v.input_names, "pitch", true, "input");
    const int torque = find(v.input_names, "gen_torque", true, "input");
    const int wind = find(v.input_names, "V_wind", false, "input");
    const int rotor_speed = find(v.output_names, "rotor_speed", true, "output");
    const int gen_speed = find(v.output_names, "GenSpeed", true, "output");
    const int azimuth = find(v.output_names, "Azimuth", false, "output");
    const int power = find(v.output_names, "GenPwr", false, "output");
    const int fa_acc = find(v.output_names, "YawBrTAxp", false, "output");
    const int ss_acc = find(v.output_names, "YawBrTAyp", false, "output");

    std::unique_ptr<runtime::DisconController> controller;
    try {
        controller =
            std::make_unique<runtime::DisconController>(library, input_file, output_root + ".SrvD");
    } catch (const std::runtime_error& e) {
        throw diag::UserError(e.what());
    }
    const runtime::InputFunction base =
        options.u_of_t ? options.u_of_t : runtime::constant_input(options.u);
    const auto nq = static_cast<std::size_t>(v.nq);
    const runtime::TimeGrid grid(options.t_start, options.t_end, options.dt);
    const std::size_t stride = runtime::output_stride(options.dt, options.dt_out);
    std::vector<double> x = options.x0, x_start, u(static_cast<std::size_t>(v.nu)),
                        u_stage(static_cast<std::size_t>(v.nu)), y(static_cast<std::size_t>(v.ny));
    // What the actuators apply (the model's inputs), from --u at the start.
    runtime::ControllerDemands applied;
    {
        base(options.t_start, u.data());
        applied.pitch = u[static_cast<std::size_t>(pitch)];
        applied.gen_torque = u[static_cast<std::size_t>(torque)];
    }
    // The step in progress: from t_step, the demands `to` held through the
    // actuators, which stood at `from`.
    double t_step = options.t_start;
    runtime::ControllerDemands from, to;
    const Actuators a = actuators;
    auto step_inputs = [&](double time, double* out) {
        base(time, out);
        out[pitch] = actuator_lag(from.pitch, to.pitch, time - t_step, a.pitch_tau);
        out[torque] = actuator_lag(from.gen_torque, to.gen_torque, time - t_step, a.torque_tau);
    };
    runtime::FixedStepper stepper(
        options.method,
        [&](double time, const double* xs, double* xdot) {
            step_inputs(time, u_stage.data());
            v.rhs(time, xs, u_stage.data(), xdot);
        },
        x.size());

    runtime::SimulationResult result;
    result.columns = runtime::column_names(v);
    result.nx = v.nx();
    result.ny = v.ny;
    auto store = [&](double t, const double* outputs) {
        result.time.push_back(t);
        result.states.insert(result.states.end(), x.begin(), x.end());
        result.outputs.insert(result.outputs.end(), outputs, outputs + v.ny);
    };
    const std::size_t last = grid.size() - 1;
    for (std::size_t k = 0;; ++k) {
        const double t = grid[k];
        // measurements at t, with the actuators' inputs in force: the outputs of row k.
        // `outputs` solves for their q'' itself: the step's first rhs at t takes
        // the inputs of the controller's new demand (through the actuators),
        // whose q'' is another (outputs_from_qdd cannot reuse it).
        base(t, u.data());
        u[static_cast<std::size_t>(pitch)] = applied.pitch;
        u[static_cast<std::size_t>(torque)] = applied.gen_torque;
        v.outputs(t, x.data(), x.data() + nq, u.data(), y.data());
        if (k == last) {
            store(t, y.data());
            break;
        }
        runtime::ControllerMeasurements m;
        m.time = t;
        m.step = grid.step();
        m.pitch = applied.pitch;
        m.gen_speed = y[static_cast<std::size_t>(gen_speed)] * pi / 30;
        m.rotor_speed = y[static_cast<std::size_t>(rotor_speed)];
        m.gen_torque = applied.gen_torque;
        m.mech_power = m.gen_torque * m.gen_speed;
        m.power = power >= 0 ? y[static_cast<std::size_t>(power)] * 1e3 : m.mech_power;
        m.wind = wind >= 0 ? u[static_cast<std::size_t>(wind)] : 0.0;
        m.tower_top_fa_acc = fa_acc >= 0 ? y[static_cast<std::size_t>(fa_acc)] : 0.0;
        m.tower_top_ss_acc = ss_acc >= 0 ? y[static_cast<std::size_t>(ss_acc)] : 0.0;
        m.azimuth =
            azimuth >= 0 ? std::fmod(y[static_cast<std::size_t>(azimuth)], 360.0) * pi / 180 : 0.0;
        runtime::ControllerDemands demand;
        try {
            demand = controller->call(m);
        } catch (const std::runtime_error& e) {
            throw diag::UserError(e.what());
        }
        // A demand that is not a number would poison the state a step later,
        // where the controller would no longer be named.
        if (!std::isfinite(demand.pitch) || !std::isfinite(demand.gen_torque)) {
            std::ostringstream msg;
            msg << "the controller demanded a pitch of " << demand.pitch << " rad and a generator "
                << "torque of " << demand.gen_torque << " N m at t = " << t << " s: not a number";
            throw diag::UserError(msg.str());
        }
        // One step with the demands held, through the actuators.
        from = applied;
        to = demand;
        t_step = t;
        if (k == 0) {
            // The first row shows the inputs of the first step at its start
            // (the demand, for ideal actuators), not the measurement's.
            step_inputs(t, u_stage.data());
            std::vector<double> y0(y.size());
            v.outputs(t, x.data(), x.data() + nq, u_stage.data(), y0.data());
            store(t, y0.data());
        } else if (k % stride == 0) {
            store(t, y.data());
        }
        const double dt = grid[k + 1] - t;
        applied.pitch = actuator_lag(from.pitch, to.pitch, dt, a.pitch_tau);
        applied.gen_torque = actuator_lag(from.gen_torque, to.gen_torque, dt, a.torque_tau);
        if (v.update_discrete) x_start = x;
        stepper.step(t, dt, x.data());
        if (v.update_discrete) {
            // The blocks' discrete states, from t to t + dt (load_block.hpp).
            std::vector<double> u_start(u_stage.size()), u_end(u_stage.size());
            step_inputs(t, u_start.data());
            step_inputs(t + dt, u_end.data());
            v.update_discrete(t, x_start.data(), u_start.data(), t + dt, x.data(), u_end.data());
        }
    }
    return result;
}

} // namespace yamsc::analysis
