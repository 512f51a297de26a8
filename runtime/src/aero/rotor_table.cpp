#include "yamsc/aero/rotor_table.hpp"

#include <cstdio>
#include <stdexcept>

namespace yamsc::aero {

namespace {

constexpr double pi = 3.14159265358979323846;

void write_row(std::ostream& out, const double* v, std::size_t n, const char* format) {
    char buf[32];
    for (std::size_t i = 0; i < n; ++i) {
        std::snprintf(buf, sizeof buf, format, v[i]);
        out << buf << (i + 1 < n ? "   " : "");
    }
    out << '\n';
}

} // namespace

runtime::PerformanceTable rotor_performance_table(const RotorInput& input,
                                                  const RotorGeometry& geometry,
                                                  const TableRequest& request) {
    if (request.tsr.empty() || request.pitch_deg.empty())
        throw std::invalid_argument("rotor table: no TSR or no pitch angle");
    if (!(request.wind_speed > 0) || !(request.rotor_radius > 0) || request.azimuths < 1)
        throw std::invalid_argument(
            "rotor table: wind speed, radius and azimuths must be positive");
    runtime::PerformanceTable t;
    t.tsr = request.tsr;
    t.pitch_deg = request.pitch_deg;
    const std::size_t n = t.tsr.size() * t.pitch_deg.size();
    t.cp.resize(n);
    t.ct.resize(n);
    t.cq.resize(n);
    RigidRotor rotor(input, geometry);
    const double U = request.wind_speed, R = request.rotor_radius;
    const double q = 0.5 * input.air_density * pi * R * R * U * U;
    const double passage = 2 * pi / static_cast<double>(input.blades.size());
    for (std::size_t i = 0; i < t.tsr.size(); ++i) {
        for (std::size_t j = 0; j < t.pitch_deg.size(); ++j) {
            OperatingPoint op;
            op.rotor_speed = t.tsr[i] * U / R;
            op.pitch = t.pitch_deg[j] * pi / 180;
            op.wind_speed = U;
            double power = 0, thrust = 0, torque = 0;
            for (int k = 0; k < request.azimuths; ++k) {
                op.azimuth = passage * k / request.azimuths;
                const RotorResult& r = rotor.evaluate(op);
                power += r.power;
                thrust += r.fxh;
                torque += r.mxh;
            }
            const double m = 1.0 / request.azimuths;
            const std::size_t at = i * t.pitch_deg.size() + j;
            t.cp[at] = m * power / (q * U);
            t.ct[at] = m * thrust / q;
            t.cq[at] = m * torque / (q * R);
        }
    }
    return t;
}

void write_performance_table(std::ostream& out, const runtime::PerformanceTable& t,
                             double wind_speed, const std::string& title) {
    out << "# ----- Rotor performance tables for " << title << " -----\n";
    out << "# ------------ Written by yamsc rotor-table from AeroDyn's steady BEM ------------\n\n";
    out << "# Pitch angle vector, " << t.pitch_deg.size()
        << " entries - x axis (matrix columns) (deg)\n";
    write_row(out, t.pitch_deg.data(), t.pitch_deg.size(), "%.4g");
    out << "# TSR vector, " << t.tsr.size() << " entries - y axis (matrix rows) (-)\n";
    write_row(out, t.tsr.data(), t.tsr.size(), "%.4g");
    out << "# Wind speed vector - z axis (m/s)\n";
    write_row(out, &wind_speed, 1, "%.4g");
    const std::pair<const char*, const std::vector<double>*> blocks[] = {
        {"Power coefficient", &t.cp}, {"Thrust coefficient", &t.ct}, {"Torque coefficient", &t.cq}};
    for (const auto& [name, values] : blocks) {
        out << "\n# " << name << "\n\n";
        for (std::size_t i = 0; i < t.tsr.size(); ++i)
            write_row(out, values->data() + i * t.pitch_deg.size(), t.pitch_deg.size(), "%.6f");
    }
}

} // namespace yamsc::aero
