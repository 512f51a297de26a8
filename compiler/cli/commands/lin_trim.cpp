// `yamsc lin` and `yamsc trim`: the linear model and the operating point.
#include "analysis/commands.hpp"
#include "cli/commands/commands.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::cli {

namespace {

using driver::LinFormat;
using driver::LinOptions;
using driver::TrimOptions;

// --rao's checks and its frequencies (RAFT's default grid: 0.005 to 0.4 Hz by 0.005).
void parse_rao(const Args& a, LinOptions& o) {
    if (o.rao.empty()) {
        if (a.has("--frequencies")) throw UsageError("--frequencies needs --rao");
        return;
    }
    if (a.get("--hydro").empty()) throw UsageError("--rao needs --hydro");
    if (o.sweep || o.mbc3 || a.has("--json") || o.format != LinFormat::table)
        throw UsageError("--rao does not take --sweep, --mbc3, --json or --format");
    const std::string f = a.has("--frequencies") ? a.get("--frequencies") : "0.005:0.005:0.4";
    o.rao_frequencies = driver::parse_sweep("f=" + f).values;
    if (o.rao_frequencies.empty() || o.rao_frequencies.front() <= 0)
        throw UsageError("--frequencies must be positive, FROM:STEP:TO in Hz");
}

LinOptions parse_lin(const Args& a) {
    LinOptions o;
    o.format = choice(a, "--format", LinFormat::table,
                      {{"table", LinFormat::table}, {"openfast-lin", LinFormat::openfast_lin}});
    const bool lin_files = o.format == LinFormat::openfast_lin;
    o.model = a.model();
    o.trim = a.has("--trim");
    o.mbc3 = a.has("--mbc3");
    o.hold = comma_list(a.get("--hold"));
    o.adjust = comma_list(a.get("--adjust"));
    if (!o.trim && !o.adjust.empty()) throw UsageError("--adjust needs --trim");
    o.azimuth = a.get("--azimuth");
    const double azimuths = a.number("--azimuths", o.azimuths);
    if (azimuths != std::floor(azimuths)) throw UsageError("--azimuths must be a whole number");
    o.azimuths = static_cast<int>(std::min(azimuths, 1e6));
    o.azimuths_given = a.has("--azimuths");
    if (!o.trim && !o.mbc3 && !o.azimuths_given && !o.hold.empty())
        throw UsageError("--hold needs --trim, --mbc3 or --azimuths");
    if (!o.mbc3 && !lin_files && (a.has("--azimuths") || a.has("--azimuth")))
        throw UsageError("--azimuths and --azimuth need --mbc3 or --format openfast-lin");
    if (o.azimuths < 1 || o.azimuths > 3600)
        throw UsageError("--azimuths must be between 1 and 3600");
    if (a.has("--sweep")) o.sweep = driver::parse_sweep(a.get("--sweep"));
    o.output = a.get("-o");
    o.plot = a.get("--plot");
    o.rao = a.get("--rao");
    if (!o.sweep && !lin_files && (!o.output.empty() || (!o.plot.empty() && o.rao.empty())))
        throw UsageError("lin writes files (-o, --plot) only for --sweep, --format or --rao");
    parse_rao(a, o);
    if (lin_files && o.output.empty()) throw UsageError("--format openfast-lin needs -o FILE.lin");
    if (lin_files && (o.sweep || !o.plot.empty()))
        throw UsageError("--format openfast-lin does not take --sweep or --plot");
    o.at = a.assignments("--at");
    o.u = a.assignments("--u");
    o.set = a.assignments("--set");
    o.sid = a.get("--sid");
    o.external = a.get("--external");
    o.json = a.has("--json");
    o.aero = a.get("--aero");
    o.wind = a.get("--wind");
    o.mooring = a.get("--mooring");
    o.hydro = a.get("--hydro");
    o.sea_state = a.get("--sea-state");
    if (o.hydro.empty() && !o.sea_state.empty()) throw UsageError("--sea-state needs --hydro");
    if (const std::string w = a.get("--wake"); w == "quasi-steady")
        o.wake = driver::Wake::quasi_steady;
    else if (!w.empty() && w != "frozen")
        throw UsageError("--wake must be frozen or quasi-steady");
    if (o.sweep && o.json) throw UsageError("--sweep writes CSV, not --json");
    o.schedule = a.get("--schedule");
    if (!o.sweep && !o.schedule.empty()) throw UsageError("--schedule needs --sweep");
    return o;
}

TrimOptions parse_trim(const Args& a) {
    TrimOptions o;
    o.model = a.model();
    o.at = a.assignments("--at");
    o.u = a.assignments("--u");
    o.set = a.assignments("--set");
    o.sid = a.get("--sid");
    o.hold = comma_list(a.get("--hold"));
    o.adjust = comma_list(a.get("--adjust"));
    o.aero = a.get("--aero");
    o.wind = a.get("--wind");
    o.mooring = a.get("--mooring");
    o.hydro = a.get("--hydro");
    o.sea_state = a.get("--sea-state");
    if (o.hydro.empty() && !o.sea_state.empty()) throw UsageError("--sea-state needs --hydro");
    o.external = a.get("--external");
    o.json = a.has("--json");
    return o;
}

/// What lin and trim share.
const char* point_help =
    R"(  --at name=v,..      the point: DOFs and rates (q=v, q'=v) over the `linearize` block
  --u name=v,..       inputs at the point
  --set name=v,..     parameter values (accept `deg`: --set theta=5deg)
  --sid body=file.sid the shape integrals of a flexible body with `symbolic modes`
  --external LIB      the model's external functions: lib.so, or file.c|file.cpp compiled
  --aero FILE         the rotor's data: a Cp/Ct/Cq table (ROSCO's format) for the
                      model's `load rotor_table`, an AeroDyn file for `load blade_elements`
  --wind V            the wind at the point (the input a load block declares as its
                      wind; a --wind SPEC's value at t = 0)
  --mooring FILE      MAP++'s or MoorDyn's lines for `load mooring` (docs/mooring.md)
  --hydro FILE        a HydroDyn file for the model's `load hydrodyn` (docs/hydrodynamics.md)
  --sea-state FILE    its SeaState file: the waves (still water without)
  --json              JSON on stdout
)";

} // namespace

Command lin_command() {
    return make_command(
        "lin", "linearize a model: M0, C0, K0, Q0, A, B and the modes; Campbell sweeps",
        R"(yamsc lin MODEL.mbd [--at name=v,..] [--u name=v,..] [--set name=v,..] [--json]
                    [--trim [--hold dof,..] [--adjust input,..]]
                    [--mbc3 [--azimuths N] [--azimuth dof]]
                    [--aero Cp_Ct_Cq.txt|AeroDyn.dat [--wake frozen|quasi-steady]] [--wind V]
                    [--mooring FILE] [--hydro HydroDyn.dat [--sea-state SeaState.dat]]
                    [--sweep NAME=FROM:STEP:TO [--schedule points.csv] [-o campbell.csv]
                                               [--plot campbell.svg]]
                    [--rao rao.csv [--frequencies FROM:STEP:TO] [--plot rao.svg]]
                    [--format openfast-lin -o case.lin [--azimuths N [--azimuth dof]]]
                    [--sid body=file.sid,..] [--external lib.so|file.c|file.cpp])",
        std::string(point_help) +
            R"(  --trim              linearize about the trimmed point (yamsc trim --help)
  --hold dof,..       DOFs trim keeps as given, or that MBC3 leaves out
  --adjust input,..   inputs trimmed to balance the spinning DOFs (with --trim)
  --mbc3              the modes of a spinning three-bladed rotor in multi-blade coordinates
  --azimuths N        linearizations over a revolution (36), 1 to 3600
  --azimuth dof       the DOF that turns the rotor
  --sweep NAME=FROM:STEP:TO  a Campbell diagram over a parameter, rate or input (CSV)
  --schedule FILE     what moves with the swept value: a steady-state table
  -o FILE             the sweep's CSV, or the .lin file(s) of --format openfast-lin
  --plot FILE         the sweep's SVG (1P/3P/6P with --mbc3)
  --wake W            blade elements (--aero AeroDyn.dat) linearized with a frozen
                      wake as OpenFAST does (frozen, default) or quasi-steady
  --format F          table (default), or openfast-lin: OpenFAST's .lin files at -o
  --rao FILE          the response per metre of wave amplitude (RAO) of each DOF in
                      regular waves, |X| and phase per frequency (CSV, with --hydro;
                      heading, and with a JONSWAP --sea-state the DOFs' standard
                      deviations, from the SeaState file; --plot: |X| as SVG)
  --frequencies F:S:T the RAOs' wave frequencies [Hz] (0.005:0.005:0.4)
Details: docs/cli.md, docs/linearization.md, docs/hydrodynamics.md.
)",
        {{"--at",     "--u",         "--set",      "--sid",        "--sweep", "-o",
          "--plot",   "--hold",      "--azimuths", "--azimuth",    "--aero",  "--wind",
          "--adjust", "--schedule",  "--format",   "--external",   "--wake",  "--mooring",
          "--hydro",  "--sea-state", "--rao",      "--frequencies"},
         {"--json", "--trim", "--mbc3"}},
        parse_lin, analysis::lin);
}

Command trim_command() {
    return make_command(
        "trim", "the operating point at rest in the model's equations (Newton on F = 0)",
        R"(yamsc trim MODEL.mbd [--at name=v,..] [--u name=v,..] [--set name=v,..] [--hold dof,..]
                     [--adjust input,..] [--aero Cp_Ct_Cq.txt] [--wind V] [--json]
                     [--mooring FILE] [--hydro HydroDyn.dat [--sea-state SeaState.dat]]
                     [--sid body=file.sid,..] [--external lib.so|file.c|file.cpp])",
        std::string(point_help) +
            R"(  --hold dof,..       DOFs kept as given (besides those with a rate)
  --adjust input,..   inputs trimmed so that nothing holds the spinning DOFs (one per rate)
Details: docs/cli.md, docs/linearization.md.
)",
        {{"--at", "--u", "--set", "--sid", "--hold", "--adjust", "--aero", "--wind", "--external",
          "--mooring", "--hydro", "--sea-state"},
         {"--json"}},
        parse_trim, analysis::trim);
}

} // namespace yamsc::cli
