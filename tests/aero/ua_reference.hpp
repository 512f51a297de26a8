#pragma once
// OpenFAST's unsteady-aerodynamics driver runs (data/reference/aero/ua*_DU25_*): the
// driver's prescribed motion (SimMod 1), its output channels, and the DU25 airfoil.
#include "aerodyn/airfoil_file.hpp"
#include "aerodyn_input/airfoil.hpp"
#include "diag/read_text.hpp"
#include "yamsc/aero/airfoil.hpp"
#include "yamsc/aero/unsteady_airfoil.hpp"

#include <cctype>
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

// The driver's deck (a run's .dvr, e.g. ua3_DU25_m8_a8_f1.dvr).
struct Driver {
    double chord = 3, speed = 60, frequency = 1, amplitude = 8 * deg, mean = 8 * deg;
    int steps_per_cycle = 400, cycles = 6;
    double d_34_to_ac = 0.5; // -Vec_AQ(2) + Vec_AT(2)
    yamsc::aero::UnsteadyModel model = yamsc::aero::UnsteadyModel::minnema_pierce; // UAMod
    bool f_lookup = true;                                                          // FLookup
    double speed_of_sound = 335;                                                   // SpdSound
    std::string airfoil = "Airfoils/DU25_A17.dat"; // AirFoil, relative to the operating deck
    double dt() const { return 1 / (frequency * steps_per_cycle); }
    int steps() const { return steps_per_cycle * cycles; }
};

// A driver deck's entries (the words before an entry's name: its value) as the
// reduced-frequency simulation (SimMod 1) uses them. Throws on what the tests
// do not model: another SimMod, a phase, UseCm False.
inline Driver read_driver(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::map<std::string, std::vector<std::string>> entries;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::vector<std::string> value;
        for (std::string w; words >> w;) {
            if (!value.empty() && std::isalpha(static_cast<unsigned char>(w.front()))) {
                entries[w] = value;
                break;
            }
            if (w.back() == ',') w.pop_back();
            value.push_back(w);
        }
    }
    auto text = [&](const std::string& name, std::size_t i = 0) {
        const auto it = entries.find(name);
        if (it == entries.end() || it->second.size() <= i)
            throw std::runtime_error(path + ": no " + name);
        return it->second[i];
    };
    auto number = [&](const std::string& name, std::size_t i = 0) {
        return std::stod(text(name, i));
    };
    auto flag = [&](const std::string& name) {
        const std::string v = text(name);
        return v == "True" || v == "true" || v == "T" || v == "t";
    };
    if (number("SimMod") != 1) throw std::runtime_error(path + ": SimMod must be 1");
    if (number("Phase") != 0) throw std::runtime_error(path + ": Phase must be 0");
    if (!flag("UseCm")) throw std::runtime_error(path + ": UseCm False is not modelled");
    Driver d;
    d.chord = number("Chord");
    d.speed = number("InflowVel");
    d.frequency = number("Frequency");
    d.amplitude = number("Amplitude") * deg;
    d.mean = number("Mean") * deg;
    d.steps_per_cycle = static_cast<int>(number("StepsPerCycle"));
    d.cycles = static_cast<int>(number("NCycles"));
    d.d_34_to_ac = -number("Vec_AQ", 1) + number("Vec_AT", 1);
    d.model = static_cast<yamsc::aero::UnsteadyModel>(static_cast<int>(number("UAMod")));
    d.f_lookup = flag("FLookup");
    d.speed_of_sound = number("SpdSound");
    d.airfoil = text("AirFoil");
    if (d.airfoil.size() >= 2 && d.airfoil.front() == '"')
        d.airfoil = d.airfoil.substr(1, d.airfoil.size() - 2);
    return d;
}

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
    return yamsc::aerodyn_input::to_airfoil(*file, model);
}

inline std::string data(const std::string& relative) {
    return std::string(YAMSC_TEST_DATA_DIR) + "/" + relative;
}

} // namespace ua_reference
