#include "yamsc/rotor_aero.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>

namespace yamsc::runtime {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double deg_per_rad = 180.0 / pi;

int index_of(const std::vector<std::string>& names, const std::string& name,
             const std::string& what) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<int>(i);
    throw std::invalid_argument("rotor aerodynamics: the model has no " + what + " '" + name + "'");
}

/// The rotor table as a load block: r = [rotor speed, hub velocity, wind, pitch].
class RotorTableBlock final : public LoadBlock {
public:
    explicit RotorTableBlock(RotorAero aero) : aero_(std::move(aero)) {
        ports_.outputs_read = {aero_.speed_output, aero_.hub_velocity_output};
        ports_.inputs_read = {aero_.wind_input, aero_.pitch_input};
        ports_.loads = {aero_.thrust_input, aero_.torque_input};
    }

    const BlockPorts& ports() const override { return ports_; }

    std::vector<std::string> output_names() const override {
        std::vector<std::string> names;
        for (const char* n : {"thrust", "torque_out", "power", "tsr", "v_rel", "cp", "ct"})
            names.push_back(aero_.name + "_" + n);
        return names;
    }

    void evaluate(double, const double*, const double* r, double* loads, double*,
                  double* out) const override {
        const RotorLoads l = at(r);
        loads[0] = l.thrust;
        loads[1] = l.torque;
        const double values[] = {l.thrust, l.torque, l.power, l.tsr, l.v_rel, l.cp, l.ct};
        for (int i = 0; i < 7; ++i) out[i] = values[i];
    }

    void derivatives(double, const double*, const double* r, BlockJacobian& j) const override {
        // V_rel = wind - hub velocity.
        const RotorLoads l = at(r);
        j.loads_z.clear();
        j.rates_z.clear();
        j.rates_r.clear();
        j.loads_r = {l.dT_dOmega, -l.dT_dV, l.dT_dV, l.dT_dpitch,
                     l.dQ_dOmega, -l.dQ_dV, l.dQ_dV, l.dQ_dpitch};
    }

private:
    RotorLoads at(const double* r) const { return rotor_loads(aero_, r[2] - r[1], r[0], r[3]); }

    RotorAero aero_;
    BlockPorts ports_;
};

} // namespace

RotorLoads rotor_loads(const RotorAero& aero, double v_rel, double omega, double pitch_rad) {
    if (!(v_rel > 0))
        throw std::invalid_argument(
            "rotor aerodynamics: the relative wind at the hub is " + std::to_string(v_rel) +
            " m/s: it must be positive (is the wind input set, e.g. yamsc --wind?)");
    RotorLoads l;
    const double R = aero.radius;
    l.v_rel = v_rel;
    l.tsr = omega * R / v_rel;
    l.pitch_deg = pitch_rad * deg_per_rad;
    const Coefficient cp = interpolate(aero.table, aero.table.cp, l.tsr, l.pitch_deg);
    const Coefficient ct = interpolate(aero.table, aero.table.ct, l.tsr, l.pitch_deg);
    const Coefficient cq = interpolate(aero.table, aero.table.cq, l.tsr, l.pitch_deg);
    l.cp = cp.value;
    l.ct = ct.value;
    l.cq = cq.value;
    const double k = 0.5 * aero.density * pi * R * R; // T = k V^2 Ct, Q = k R V^2 Cq
    l.thrust = k * v_rel * v_rel * ct.value;
    l.torque = k * R * v_rel * v_rel * cq.value;
    l.power = l.torque * omega;
    // dlambda/dV = -lambda/V, dlambda/dOmega = R/V, dbeta_deg/dbeta = 180/pi
    l.dT_dV = k * (2 * v_rel * ct.value - v_rel * l.tsr * ct.d_tsr);
    l.dT_dOmega = k * R * v_rel * ct.d_tsr;
    l.dT_dpitch = k * v_rel * v_rel * ct.d_pitch * deg_per_rad;
    l.dQ_dV = k * R * (2 * v_rel * cq.value - v_rel * l.tsr * cq.d_tsr);
    l.dQ_dOmega = k * R * R * v_rel * cq.d_tsr;
    l.dQ_dpitch = k * R * v_rel * v_rel * cq.d_pitch * deg_per_rad;
    return l;
}

RotorAero bind_rotor_aero(const ModelView& view, PerformanceTable table, double radius,
                          double density, const std::string& wind, const std::string& pitch,
                          const std::string& thrust, const std::string& torque,
                          const std::string& speed, const std::string& hub_velocity) {
    if (!(radius > 0) || !(density > 0))
        throw std::invalid_argument("rotor aerodynamics: radius and density must be positive");
    RotorAero a;
    a.table = std::move(table);
    a.radius = radius;
    a.density = density;
    a.wind_input = index_of(view.input_names, wind, "input");
    a.pitch_input = pitch.empty() ? -1 : index_of(view.input_names, pitch, "input");
    a.thrust_input = index_of(view.input_names, thrust, "input");
    a.torque_input = index_of(view.input_names, torque, "input");
    a.speed_output = index_of(view.output_names, speed, "output");
    a.hub_velocity_output = index_of(view.output_names, hub_velocity, "output");
    return a;
}

std::shared_ptr<const LoadBlock> rotor_table_block(RotorAero aero) {
    return std::make_shared<const RotorTableBlock>(std::move(aero));
}

ModelView with_rotor_aero(const ModelView& base, const RotorAero& aero) {
    return close_blocks(base, {rotor_table_block(aero)});
}

} // namespace yamsc::runtime
