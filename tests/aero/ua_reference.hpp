#pragma once
// OpenFAST's unsteady-aerodynamics driver runs (data/reference/aero/ua*_DU25_*): the
// driver's prescribed motion (SimMod 1), its output channels, and the DU25 airfoil.
#include "aerodyn/airfoil_file.hpp"
#include "analysis/aerodyn_airfoil.hpp"
#include "diag/read_text.hpp"
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

// An AeroDyn airfoil file as the unsteady models read it (AeroDyn's reader, the
// constants the file leaves out computed as AirfoilInfo does for `model`).
inline yamsc::aero::Airfoil read_airfoil(const std::string& path,
                                         yamsc::aero::UnsteadyModel model) {
    yamsc::diag::Diagnostics diags;
    const auto text = yamsc::diag::read_text_file(path, diags);
    if (!text) throw std::runtime_error("cannot open " + path);
    const auto file = yamsc::aerodyn::read_airfoil_file(text, {}, diags);
    if (!file) throw std::runtime_error("cannot read " + path);
    return yamsc::analysis::to_airfoil(*file, model);
}

inline std::string data(const std::string& relative) {
    return std::string(YAMSC_TEST_DATA_DIR) + "/" + relative;
}

} // namespace ua_reference
