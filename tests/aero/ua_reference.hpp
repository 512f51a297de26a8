#pragma once
// OpenFAST's unsteady-aerodynamics driver runs (data/reference/aero/ua*_DU25_*): the
// driver's prescribed motion (SimMod 1), its output channels, and the DU25 airfoil.
#include "yamsc/aero/airfoil.hpp"
#include "yamsc/aero/unsteady_airfoil.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ua_reference {

constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi / 180;

// The driver's deck (ua*_DU25_m8_a8_f1.dvr).
struct Driver {
    double chord = 3, speed = 60, frequency = 1, amplitude = 8 * deg, mean = 8 * deg;
    int steps_per_cycle = 400, cycles = 6;
    double d_34_to_ac = 0.5; // -Vec_AQ(2) + Vec_AT(2)
    double dt() const { return 1 / (frequency * steps_per_cycle); }
    int steps() const { return steps_per_cycle * cycles; }
};

// UA's inputs at step n = 1, 2, ... (setUAinputsAlphaSim: the airfoil pitches about
// mid-chord, U is the speed at 3/4 chord).
inline yamsc::aero::UnsteadyInput driver_input(const Driver& d, int n) {
    const double phase = (n - 1) * 2 * pi / d.steps_per_cycle;
    const double alpha_ref = d.amplitude * std::sin(phase) + d.mean;
    const double omega = d.amplitude * std::cos(phase) * 2 * pi / d.steps_per_cycle / d.dt();
    yamsc::aero::UnsteadyInput u;
    u.omega = omega;
    u.v_ac_n = std::sin(alpha_ref) * d.speed - omega * d.d_34_to_ac / 2 * d.chord;
    u.v_ac_c = std::cos(alpha_ref) * d.speed;
    u.alpha = std::atan2(u.v_ac_n, u.v_ac_c);
    u.U = std::hypot(u.v_ac_n + omega * 0.5 * d.chord, u.v_ac_c);
    return u;
}

// Columns of a CSV with a header line, by name.
struct Csv {
    std::map<std::string, std::vector<double>> columns;
    const std::vector<double>& operator[](const std::string& name) const {
        auto it = columns.find(name);
        if (it == columns.end()) throw std::runtime_error("no column " + name);
        return it->second;
    }
};

inline Csv read_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::string line, cell;
    std::getline(in, line);
    std::vector<std::string> names;
    for (std::stringstream ss(line); std::getline(ss, cell, ',');) names.push_back(cell);
    Csv csv;
    while (std::getline(in, line)) {
        std::stringstream ss(line);
        for (const auto& name : names) {
            std::getline(ss, cell, ',');
            csv.columns[name].push_back(std::stod(cell));
        }
    }
    return csv;
}

// The first table of an AeroDyn airfoil file with its UA constants; the constants the
// file leaves out (alphaUpper, alphaLower, C_lalpha) as AirfoilInfo computes them.
inline yamsc::aero::Airfoil read_airfoil(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::map<std::string, std::string> values;
    std::vector<std::vector<double>> rows;
    std::string line;
    int table_rows = -1;
    while (std::getline(in, line)) {
        if (line.empty() || line.find_first_not_of(" \t") == std::string::npos) continue;
        if (line[line.find_first_not_of(" \t")] == '!') continue;
        std::stringstream ss(line);
        if (table_rows > 0) {
            std::vector<double> row;
            for (double v; ss >> v;) row.push_back(v);
            rows.push_back(row);
            if (static_cast<int>(rows.size()) == table_rows) break;
            continue;
        }
        std::string value, key;
        ss >> value >> key;
        values[key] = value;
        if (key == "NumAlf") table_rows = std::stoi(value);
    }
    yamsc::aero::Airfoil af;
    af.name = path;
    yamsc::aero::PolarTable t;
    for (const auto& r : rows) {
        t.alpha.push_back(r.at(0) * deg);
        t.cl.push_back(r.at(1));
        t.cd.push_back(r.at(2));
        if (r.size() > 3) t.cm.push_back(r[3]);
    }
    auto num = [&](const char* key) { return std::stod(values.at(key)); };
    yamsc::aero::UnsteadyConstants k;
    k.alpha0 = num("alpha0") * deg;
    k.alpha1 = num("alpha1") * deg;
    k.alpha2 = num("alpha2") * deg;
    k.eta_e = num("eta_e");
    k.C_nalpha = num("C_nalpha");
    k.T_f0 = num("T_f0");
    k.T_V0 = num("T_V0");
    k.T_p = num("T_p");
    k.T_VL = num("T_VL");
    k.b1 = num("b1");
    k.b2 = num("b2");
    k.b5 = num("b5");
    k.A1 = num("A1");
    k.A2 = num("A2");
    k.A5 = num("A5");
    k.Cn1 = num("Cn1");
    k.Cn2 = num("Cn2");
    k.St_sh = num("St_sh");
    k.Cd0 = num("Cd0");
    k.Cm0 = num("Cm0");
    k.x_cp_bar = num("x_cp_bar");
    const auto range = yamsc::aero::attached_range_defaults(t, k.Cd0);
    k.alphaUpper = range.alpha_upper;
    k.alphaLower = range.alpha_lower;
    k.C_lalpha = range.cl_alpha;
    t.unsteady = k;
    af.tables.push_back(t);
    return af;
}

inline std::string data(const std::string& relative) {
    return std::string(YAMSC_TEST_DATA_DIR) + "/" + relative;
}

} // namespace ua_reference
