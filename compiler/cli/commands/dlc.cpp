// `yamsc dlc`: IEC 61400-1 design load cases as a batch folder.
#include "analysis/dlc.hpp"
#include "cli/commands/commands.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::cli {

namespace {

using analysis::DesignLoadCase;
using analysis::DlcOptions;

std::vector<double> numbers(const Args& a, const std::string& name) {
    std::vector<double> values;
    for (const std::string& s : comma_list(a.get(name)))
        values.push_back(driver::parse_value(s, name));
    return values;
}

void parse_class(const std::string& s, DlcOptions& o) {
    static const std::vector<std::pair<std::string, analysis::TurbineClass>> classes{
        {"III", analysis::TurbineClass::III},
        {"II", analysis::TurbineClass::II},
        {"I", analysis::TurbineClass::I}};
    for (const auto& [roman, c] : classes)
        if (s.size() == roman.size() + 1 && s.compare(0, roman.size(), roman) == 0 &&
            std::string("ABC").find(s.back()) != std::string::npos) {
            o.turbine_class = c;
            o.turbulence = s.back() == 'A'   ? analysis::TurbulenceCategory::A
                           : s.back() == 'B' ? analysis::TurbulenceCategory::B
                                             : analysis::TurbulenceCategory::C;
            return;
        }
    throw UsageError("--class takes the turbine class and the turbulence "
                     "category: IA, IB, IC, "
                     "IIA, .., IIIC, not '" +
                     s + "'");
}

DlcOptions parse_dlc(const Args& a) {
    DlcOptions o;
    o.model = a.model();
    o.output_dir = a.get("-o");
    if (o.output_dir.empty()) throw UsageError("dlc needs -o FOLDER");
    if (a.has("--dlc")) {
        o.cases.clear();
        for (const std::string& s : comma_list(a.get("--dlc"))) {
            static const std::vector<std::pair<std::string, DesignLoadCase>> names{
                {"1.1", DesignLoadCase::dlc1_1},
                {"1.2", DesignLoadCase::dlc1_2},
                {"1.3", DesignLoadCase::dlc1_3},
                {"6.1", DesignLoadCase::dlc6_1},
                {"6.2", DesignLoadCase::dlc6_2}};
            auto it = std::find_if(names.begin(), names.end(),
                                   [&](const auto& n) { return n.first == s; });
            if (it == names.end())
                throw UsageError("--dlc takes 1.1, 1.2, 1.3, 6.1 and 6.2, not '" + s + "'");
            if (std::find(o.cases.begin(), o.cases.end(), it->second) == o.cases.end())
                o.cases.push_back(it->second);
        }
    }
    if (a.has("--class")) parse_class(a.get("--class"), o);
    o.hub_height = a.number("--hub-height", 0);
    o.rotor_diameter = a.number("--rotor-diameter", 0);
    o.cut_in = a.number("--cut-in", o.cut_in);
    o.cut_out = a.number("--cut-out", o.cut_out);
    o.bin = a.number("--bin", o.bin);
    if (a.has("--speeds")) o.speeds = numbers(a, "--speeds");
    const double seeds = a.number("--seeds", o.seeds);
    if (seeds != std::floor(seeds)) throw UsageError("--seeds must be a whole number");
    o.seeds = static_cast<int>(seeds);
    const double base = a.number("--seed", 1);
    if (base != std::floor(base) || std::fabs(base) > 2e9)
        throw UsageError("--seed must be a whole number");
    o.seed_base = static_cast<std::int64_t>(base);
    if (a.has("--yaw")) o.yaw = numbers(a, "--yaw");
    o.parked_yaw = a.number("--parked-yaw", o.parked_yaw);
    o.yaw_step = a.number("--yaw-step", o.yaw_step);
    o.controller = a.get("--controller");
    o.controller_input = a.get("--controller-input");
    o.aero = a.get("--aero");
    o.parked_model = a.get("--parked-model");
    o.parked_u = a.get("--parked-u", o.parked_u);
    o.dt = a.number("--dt", o.dt);
    o.dt_out = a.number("--dt-out", o.dt_out);
    o.time = a.number("--time", o.time);
    o.transient = a.number("--transient", o.transient);
    if (!(o.dt > 0) || !(o.dt_out > 0) || !(o.time > 0) || !(o.transient >= 0))
        throw UsageError("--dt, --dt-out and --time must be positive, --transient not negative");
    const double points = a.number("--grid", o.grid_points);
    if (points != std::floor(points) || points < 2 || points > 200)
        throw UsageError("--grid takes the points across (and up): 2 .. 200");
    o.grid_points = static_cast<int>(points);
    o.grid_size = a.number("--grid-size", 0);
    o.wind_dt = a.number("--wind-dt", o.wind_dt);
    o.shear = a.number("--shear", o.shear);
    o.write_bts = !a.has("--no-bts");
    const double threads = a.number("--threads", 0);
    if (a.has("--threads") && (threads != std::floor(threads) || threads < 1 || threads > 4096))
        throw UsageError("--threads must be a whole number >= 1");
    o.threads = static_cast<int>(threads);
    return o;
}

} // namespace

Command dlc_command() {
    return make_command(
        "dlc",
        "IEC 61400-1 design load cases as a batch folder: winds, InflowWind "
        "files, manifest",
        "yamsc dlc MODEL.mbd -o FOLDER --hub-height H --rotor-diameter D [--dlc "
        "1.1,1.2,1.3,6.1,6.2]\n"
        "             [--class IB] [--cut-in V --cut-out V --bin W | --speeds "
        "V,..] [--seeds N] [--seed S]\n"
        "             [--yaw DEG,..] [--parked-yaw DEG] [--yaw-step DEG] "
        "[--controller LIB\n"
        "             [--controller-input FILE]] [--aero FILE] [--parked-model "
        "FILE] [--parked-u "
        "name=v,..]\n"
        "             [--dt DT] [--dt-out DT] [--time T] [--transient T] [--grid "
        "N] [--grid-size M]\n"
        "             [--wind-dt DT] [--shear A] [--no-bts] [--threads N]",
        R"(  MODEL.mbd           the operating turbine (its controller's inputs pitch and gen_torque)
  -o FOLDER           the batch folder: cases.csv, table.csv, wind/ (docs/dlc.md)
  --hub-height H      [m] (required)
  --rotor-diameter D  [m] (required): the wind grid covers 1.15 D (--grid-size)
  --dlc LIST          1.1 and 1.2 (NTM), 1.3 (ETM), 6.1 (parked, EWM 50-year, yaw +-8 deg),
                      6.2 (parked, EWM 50-year, grid loss: yaw -180 .. 180) (default: 1.2)
  --class IB          turbine class I, II or III and turbulence category A, B or C (default IB)
  --cut-in V, --cut-out V, --bin W  the operating speeds: bin centres (default 3, 25, 2 m/s)
  --speeds V,..       the operating speeds, instead of the bins
  --seeds N           turbulence seeds per speed (default 6)
  --seed S            the first wind's RandSeed1 (default 1; docs/dlc.md)
  --yaw DEG,..        DLC 1.x yaw misalignments (default 0), e.g. -8,0,8
  --parked-yaw DEG    DLC 6.1's misalignment, +- (default 8)
  --yaw-step DEG      DLC 6.2's step from -180 deg (default 30)
  --controller LIB    the operating cases' DISCON library
  --controller-input F  its input file
  --aero FILE         the rotor's data (as sim --aero), every case
  --parked-model FILE the parked cases' model (default MODEL: idling; a model without the
                      generator DOF for a locked rotor)
  --parked-u LIST     the parked cases' inputs (default pitch=90deg,gen_torque=0)
  --dt DT, --dt-out DT  the step and the output step (default 0.01, 0.05 s)
  --time T            the time kept (default 600 s)
  --transient T       the start-up simulated before it and dropped (default 60 s)
  --grid N            the wind grid: N x N points (default 15)
  --grid-size M       its width and height [m] (default 1.15 D, rounded up)
  --wind-dt DT        the wind field's time step (default 0.05 s)
  --shear A           the power law of NTM and ETM (default 0.2; EWM: 0.11)
  --no-bts            the TurbSim inputs only, not the .bts files
  --threads N         fields made at a time (default: one per core)
)",
        {{"-o",           "--hub-height",   "--rotor-diameter", "--dlc",
          "--class",      "--cut-in",       "--cut-out",        "--bin",
          "--speeds",     "--seeds",        "--seed",           "--yaw",
          "--parked-yaw", "--yaw-step",     "--controller",     "--controller-input",
          "--aero",       "--parked-model", "--parked-u",       "--dt",
          "--dt-out",     "--time",         "--transient",      "--grid",
          "--grid-size",  "--wind-dt",      "--shear",          "--threads"},
         {"--no-bts"}},
        parse_dlc, analysis::dlc);
}

} // namespace yamsc::cli
