#include "analysis/rotor_aero_setup.hpp"

#include "diag/errors.hpp"

#include <yamsc/performance_table.hpp>
#include <yamsc/rotor_aero.hpp>
#include <yamsc/wind.hpp>

#include <stdexcept>

namespace yamsc::analysis {

using diag::UsageError;
using diag::UserError;

using diag::UsageError;
using diag::UserError;

namespace {

double param_value(const Loaded& l, const std::string& name) {
    const int i = l.library->param_index(name);
    if (i < 0)
        throw UserError("--aero: the model has no parameter '" + name +
                        "' (the rotor block reads rotor_radius [m] and air_density [kg/m^3])");
    return l.params[static_cast<std::size_t>(i)];
}

bool has(const std::vector<std::string>& names, const std::string& name) {
    for (const std::string& n : names)
        if (n == name) return true;
    return false;
}

} // namespace

runtime::ModelView close_rotor_aero(const Loaded& l, const std::string& table_path) {
    try {
        runtime::PerformanceTable table = runtime::read_performance_table(table_path);
        const std::string pitch = has(l.view.input_names, "pitch") ? "pitch" : "";
        const runtime::RotorAero aero = runtime::bind_rotor_aero(
            l.view, std::move(table), param_value(l, "rotor_radius"), param_value(l, "air_density"),
            "V_wind", pitch, "thrust", "aero_torque", "rotor_speed", "hub_shaft_velocity");
        return runtime::with_rotor_aero(l.view, aero);
    } catch (const std::invalid_argument& e) {
        throw UserError(std::string("--aero: ") + e.what());
    } catch (const std::runtime_error& e) {
        throw UserError(std::string("--aero: ") + e.what());
    }
}

int wind_input_index(const runtime::ModelView& v) {
    for (std::size_t i = 0; i < v.input_names.size(); ++i)
        if (v.input_names[i] == "V_wind") return static_cast<int>(i);
    throw UserError("--wind: the model has no input 'V_wind' (the hub-height wind [m/s])");
}

runtime::InputFunction wind_inputs(const runtime::ModelView& v, std::vector<double> u,
                                   const std::string& spec) {
    const int w = wind_input_index(v);
    runtime::WindSignal wind;
    try {
        wind = runtime::parse_wind(spec);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    } catch (const std::runtime_error& e) {
        throw UserError(e.what());
    }
    return [u = std::move(u), wind = std::move(wind), w](double t, double* out) {
        for (std::size_t i = 0; i < u.size(); ++i) out[i] = u[i];
        out[w] = wind(t);
    };
}

void set_wind_at_start(const runtime::ModelView& v, std::vector<double>& u,
                       const std::string& spec) {
    std::vector<double> out(u.size());
    wind_inputs(v, u, spec)(0.0, out.data());
    u = out;
}

} // namespace yamsc::analysis
