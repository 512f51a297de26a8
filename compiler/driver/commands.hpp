#pragma once
// The commands of `yamsc` as library functions: each takes its options, writes
// its results to `out`, diagnostics and progress to `err`, and returns the exit
// status (0 success, 1 user error). Usage errors throw UsageError, internal
// errors diag::InternalError; the CLI turns them into exit statuses 2 and 70.
// The options of every command are here; each command is declared by the stage
// that runs it: compile, check, eval and sid below, from_openfast in
// openfast/from_openfast.hpp, the rest in analysis/commands.hpp.
//
// Options arrive typed: the CLI (compiler/cli/) parses and validates every
// option once; the commands never compare option strings.
#include "driver/values.hpp"

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace yamsc::driver {

enum class Language { cpp, c, latex };
/// --dump: print an intermediate form and stop.
enum class Dump { none, ast, model, module };
/// --real: the floating-point type of generated C.
enum class Real { double_precision, single_precision };

/// How the derivatives are formed (docs/benchmarks.md): `unrolled`, M and
/// every Jacobian entry as its own expression (fastest code for small models);
/// `tangent`, M a and one directional derivative, evaluated column by column
/// in generated loops (code and compile time O(n²) instead of O(n³) for an
/// n-body chain); `automatic`: tangent from `tangent_form_min_dofs` DOFs on,
/// unless the model has `approx` (which works on M itself).
enum class Derivatives { automatic, unrolled, tangent };
inline constexpr std::size_t tangent_form_min_dofs = 25;

enum class SimMethod { rk4, abm4, cvode };
/// How `sim` couples the load blocks to the structure within a step
/// (runtime::Coupling): at every stage, or once per step with the loads
/// extrapolated, as OpenFAST's ModCoupling 1.
enum class SimCoupling { tight, loose };
/// --channels: outputs as the model names them, or as OpenFAST's channels.
enum class Channels { all, openfast };

struct CompileOptions {
    std::string model;
    std::string output;                     // -o
    std::string header;                     // --header
    Language lang = Language::cpp;          // --lang, or from the extension of -o
    std::string name_space;                 // --namespace
    Dump dump = Dump::none;                 // --dump ast|model|module
    std::string depfile;                    // --depfile: make-style dependencies of the output
    std::optional<Real> real;               // --real (C only); none: double, not recorded
    std::optional<Derivatives> jacobians;   // --jacobians; none: automatic, not recorded
    std::vector<std::string> sensitivities; // --sensitivities p1,p2: d(M0,C0,K0)/dp routine
    bool verbose = false;                   // progress of each stage on stderr
};

struct CheckOptions {
    std::string model;
    bool json = false;
};

struct EvalOptions {
    std::string model;
    std::vector<double> q, qd;      // empty: zeros
    std::vector<Assignment> u, set; // --u, --set
    std::string sid;                // --sid body=file.sid,..
    std::string external;           // --external lib.so|file.c|file.cpp: runs the compiled code
    double t = 0;
    bool json = true;
    bool compiled = false; // --compiled: from the compiled code (eval_compiled.cpp)
};

/// --wake of `lin`: how blade elements' loads are differentiated.
enum class Wake {
    frozen,       // the inductions' velocities held at the point's (OpenFAST's linearization)
    quasi_steady, // the BEM solved again at every perturbed point
};

/// --format of `lin`: the modes as a table (or --json), or OpenFAST's .lin files too.
enum class LinFormat { table, openfast_lin };

struct LinOptions {
    std::string model;
    std::vector<Assignment> at, set, u;
    bool trim = false;               // --trim: linearize about the trimmed point
    std::vector<std::string> hold;   // --hold: DOFs trim keeps / MBC3 leaves out (with a rate: too)
    std::vector<std::string> adjust; // --adjust: inputs trimmed to balance the spinning DOFs
    bool mbc3 = false;               // --mbc3: azimuth-averaged multi-blade coordinates
    int azimuths = 36;               // --azimuths: linearizations over a revolution
    bool azimuths_given = false;     // --azimuths given (openfast-lin: one file per azimuth)
    LinFormat format = LinFormat::table; // --format openfast-lin: .lin files at -o
    std::string azimuth;                 // --azimuth: the DOF that turns the rotor
    std::string sid;                     // --sid body=file.sid,..
    std::string external;                // --external lib.so|file.c|file.cpp
    bool json = false;
    std::optional<Sweep> sweep;   // --sweep NAME=FROM:STEP:TO: a Campbell diagram
    std::string schedule;         // --schedule FILE: what moves with the swept value
    std::string output;           // -o: its CSV (default: stdout)
    std::string plot;             // --plot: its SVG
    std::string aero;             // --aero TABLE: the quasi-steady rotor block (Cp/Ct/Cq table)
    std::string wind;             // --wind SPEC: V_wind at the operating point (its value at t = 0)
    std::string mooring;          // --mooring MAP.dat: the lines of the model's `load mooring`
    std::string hydro, sea_state; // --hydro HydroDyn.dat, --sea-state SeaState.dat
    Wake wake = Wake::frozen;     // --wake: blade elements' wake in the linear model
    std::string rao;              // --rao: the RAOs' CSV (with --hydro)
    std::vector<double> rao_frequencies; // --frequencies FROM:STEP:TO [Hz] of --rao
};

struct TrimOptions {
    std::string model;
    std::vector<Assignment> at, set, u; // the starting point, as for lin
    std::string sid;
    std::string external;            // --external, as for lin
    std::vector<std::string> hold;   // DOFs kept as given (besides those with a rate)
    std::vector<std::string> adjust; // inputs trimmed so that nothing holds the spinning DOFs
    std::string aero;                // --aero TABLE, as for lin
    std::string wind;                // --wind SPEC (its value at t = 0)
    std::string mooring;             // --mooring MAP.dat, as for lin
    std::string hydro, sea_state;    // --hydro HydroDyn.dat, --sea-state SeaState.dat
    bool json = false;
};

struct SimOptions {
    std::string model;
    double tmax = 0, dt = 0;
    double dt_out = 0; // --dt-out: the time between rows (a multiple of dt); 0: every step
    std::vector<Assignment> ic, u, set;
    std::string sid;      // --sid body=file.sid,..
    std::string external; // --external lib.so|file.c|file.cpp
    SimMethod method = SimMethod::rk4;
    std::string output; // CSV path; empty: summary only
    double rtol = 1e-8, atol = 1e-10;
    bool verbose = false;
    Channels channels = Channels::all;      // --channels all|openfast
    std::string compare;                    // reference table: print the error per channel
    std::string plot;                       // SVG of the channels (with the reference)
    std::vector<std::string> plot_channels; // --plot-channels; empty: compared or all
    std::string vtk;                        // --vtk DIR: the scene and the CSV (empty: none)
    bool linear = false;                    // integrate the linear model about --at / linearize
    std::vector<Assignment> at;             // --at: the operating point of --linear
    std::string aero;    // --aero TABLE: the quasi-steady rotor block (Cp/Ct/Cq table)
    std::string wind;    // --wind SPEC: V_wind steady, step:V0:V1:t=T or a CSV (time, speed)
    std::string mooring; // --mooring MAP.dat: the lines of the model's `load mooring`
    std::string hydro, sea_state;              // --hydro HydroDyn.dat, --sea-state SeaState.dat
    std::string controller;                    // --controller LIB: a DISCON library in the loop
    std::string controller_input;              // --controller-input FILE: its accINFILE
    SimCoupling coupling = SimCoupling::tight; // --coupling tight|loose
    int interp_order = 2;                      // --interp-order: loose coupling's extrapolation
};

/// `yamsc batch MANIFEST` (docs/batch.md): one `sim` per manifest row.
struct BatchOptions {
    std::string manifest;
    std::string output_dir;     // -o; empty: the manifest's name without .csv, plus ".out"
    int threads = 0;            // --threads; 0: one per core
    int shard = 1, shards = 1;  // --shard k/N: the rows whose index mod N is k - 1
    bool quiet = false;         // -q: no progress on stderr
    double case_time_limit = 0; // --case-time-limit [s]; 0: none (a row's time_limit wins)
    /// SIGINT/SIGTERM stop the run after the cases in progress (the command
    /// line; not a library caller such as a Python worker, whose signals are
    /// its own).
    bool stop_on_signal = false;
};

/// `yamsc batch merge DIR...`: the shards' summaries as one.
struct BatchMergeOptions {
    std::vector<std::string> dirs;
    std::string output; // -o; empty: summary.csv in the first folder
};

/// What `from-openfast` makes of AeroDyn (`--aero`): its blade elements on the
/// flexible blades, or the quasi-steady rotor of a Cp/Ct/Cq table.
enum class RotorAero { blade_elements, table };

struct FromOpenFastOptions {
    std::string deck;                               // ElastoDyn main file or .fst
    std::vector<std::pair<std::string, bool>> dofs; // --dofs NAME=on|off (ElastoDyn flag names)
    std::string output;                             // -o model.mbd
    std::string cp_table; // --cp-table: the rotor block's table (default: the controller's)
    RotorAero aero = RotorAero::blade_elements; // --aero blade-elements|table
};

struct SidOptions {
    std::string tower, blade;       // --elastodyn-tower / --elastodyn-blade
    double length = 0;              // --length [m]
    std::vector<std::string> modes; // --modes fa1,ss1 (default: all first modes)
    int stations = 50;              // --stations: integration stations and SID nodes
    std::string output;             // -o; empty or "-": stdout
};

/// --fmi-version of `yamsc fmu`: the standard its modelDescription.xml follows.
enum class FmiVersion { fmi3, fmi2 };

/// `yamsc fmu`: the model as an FMI unit (model exchange and co-simulation).
struct FmuOptions {
    std::string model;
    std::string output;                    // -o model.fmu
    FmiVersion version = FmiVersion::fmi3; // --fmi-version 3|2
    SimMethod method = SimMethod::rk4;     // --method: the co-simulation step's integrator
    double step = 0;                       // --step DT: its fixed step [s]; 0: the default
    std::vector<Assignment> set;           // --set: the parameters' start values
    std::string external;                  // --external file.c|file.cpp compiled into the unit
    std::string aero;                      // --aero FILE: carried under resources/
    std::string wind;                      // --wind SPEC: a file is carried under resources/
    std::string depfile;                   // --depfile: make-style dependencies of -o
    bool verbose = false;
};

struct RotorTableOptions {
    std::string table;                  // a Cp/Ct/Cq table in ROSCO's format, or a .fst deck
    std::string output;                 // -o rotor_table.c (a table: -o Cp_Ct_Cq.txt from a deck)
    std::string prefix = "rotor_table"; // --prefix: of every name in the file
    // From a deck: the grids, the wind speed, the azimuths averaged.
    std::vector<double> tsr, pitch_deg; // --tsr, --pitch
    double wind = 11.4;                 // --wind [m/s]
    int azimuths = 6;                   // --azimuths per blade passage
};

/// `yamsc turbulence`: IEC Kaimal turbulence as a TurbSim .bts file. Each option
/// given replaces the input file's entry (without a file, the options are all).
enum class TurbulenceCharacteristicOption { A, B, C, percent };
enum class TurbulenceModelOption { ntm, etm1, etm2, etm3 }; // NTM, 1ETM, 2ETM, 3ETM
enum class TurbulenceProfileOption { power_law, logarithmic };
struct TurbulenceOptions {
    std::string input;                                            // a TurbSim input file, or empty
    std::string output;                                           // -o FILE.bts
    std::optional<TurbulenceCharacteristicOption> characteristic; // --class
    double intensity_percent = 0;                                 // --class 12.5
    std::optional<TurbulenceModelOption> model;                   // --model
    std::optional<TurbulenceProfileOption> profile;               // --profile
    std::optional<double> speed, hub_height, ref_height; // --speed, --hub-height, --ref-height
    std::optional<int> ny, nz;                           // --grid NYxNZ
    std::optional<double> width, height;                 // --size W[xH]
    std::optional<double> time_step, time;               // --dt, --time
    std::optional<std::int64_t> seed;                    // --seed
    std::optional<double> shear, roughness;              // --shear, --roughness
    std::optional<int> scale;                            // --scale 0|1|2
    bool periodic = false;                               // --periodic
};

/// `yamsc view`: a run written by `sim --vtk` as one HTML page (docs/viewer.md).
struct ViewOptions {
    std::string run;                   // the RUN folder or its .pvd
    std::string output;                // -o page.html (default: <model>.html beside the .pvd)
    std::vector<std::string> channels; // --channels a,b (default: a few the page chooses)
    bool no_channels = false;          // --channels none: the scene alone
    std::string title;                 // --title (default: the model's name)
    double frame_rate = 30;            // --fps: frames kept per second of the run
};

int compile(const CompileOptions& o, std::ostream& out, std::ostream& err);
int check(const CheckOptions& o, std::ostream& out, std::ostream& err);
int eval(const EvalOptions& o, std::ostream& out, std::ostream& err);
int sid(const SidOptions& o, std::ostream& out, std::ostream& err);

} // namespace yamsc::driver
