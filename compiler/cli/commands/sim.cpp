// `yamsc sim`: one simulation of a model.
#include "analysis/commands.hpp"
#include "cli/commands/commands.hpp"

#include <cmath>

namespace yamsc::cli {

namespace {

using driver::Channels;
using driver::SimMethod;
using driver::SimOptions;

SimOptions parse_sim(const Args& a) {
    SimOptions o;
    o.model = a.model();
    if (!a.has("--tmax") || !a.has("--dt")) throw UsageError("sim needs --tmax and --dt");
    o.tmax = a.number("--tmax", 0);
    o.dt = a.number("--dt", 0);
    if (!(o.tmax > 0) || !(o.dt > 0)) throw UsageError("--tmax and --dt must be positive");
    o.dt_out = a.number("--dt-out", 0);
    if (a.has("--dt-out")) {
        // As runtime::output_stride checks it (the CLI does not link the runtime).
        const double steps = o.dt_out / o.dt;
        if (!(o.dt_out > 0) || std::round(steps) < 1 ||
            std::fabs(steps - std::round(steps)) > 1e-9 * std::round(steps))
            throw UsageError("--dt-out must be a positive multiple of --dt");
    }
    o.ic = a.assignments("--ic");
    o.u = a.assignments("--u");
    o.set = a.assignments("--set");
    o.sid = a.get("--sid");
    o.external = a.get("--external");
    o.method =
        choice(a, "--method", SimMethod::rk4,
               {{"rk4", SimMethod::rk4}, {"abm4", SimMethod::abm4}, {"cvode", SimMethod::cvode}});
    o.rtol = a.number("--rtol", o.rtol);
    o.atol = a.number("--atol", o.atol);
    o.output = a.get("-o");
    o.verbose = a.has("-v");
    o.channels = choice(a, "--channels", Channels::all,
                        {{"all", Channels::all}, {"openfast", Channels::openfast}});
    o.compare = a.get("--compare");
    o.plot = a.get("--plot");
    o.plot_channels = comma_list(a.get("--plot-channels"));
    o.vtk = a.get("--vtk");
    o.linear = a.has("--linear");
    o.at = a.assignments("--at");
    if (!o.at.empty() && !o.linear) throw UsageError("--at needs --linear");
    o.aero = a.get("--aero");
    o.wind = a.get("--wind");
    o.mooring = a.get("--mooring");
    o.hydro = a.get("--hydro");
    o.sea_state = a.get("--sea-state");
    if (o.hydro.empty() && !o.sea_state.empty()) throw UsageError("--sea-state needs --hydro");
    o.controller = a.get("--controller");
    o.controller_input = a.get("--controller-input");
    if (o.controller.empty() && !o.controller_input.empty())
        throw UsageError("--controller-input needs --controller");
    if (!o.controller.empty() && (o.linear || o.method == SimMethod::cvode))
        throw UsageError("--controller runs with RK4 or ABM4 on the nonlinear model");
    o.coupling =
        choice(a, "--coupling", driver::SimCoupling::tight,
               {{"tight", driver::SimCoupling::tight}, {"loose", driver::SimCoupling::loose}});
    if (o.coupling == driver::SimCoupling::loose && o.method == SimMethod::cvode)
        throw UsageError("--coupling loose steps with RK4 or ABM4 (CVODE couples tightly)");
    o.interp_order = static_cast<int>(a.number("--interp-order", 2));
    if (a.has("--interp-order") && o.coupling != driver::SimCoupling::loose)
        throw UsageError("--interp-order needs --coupling loose");
    if (o.interp_order < 0 || o.interp_order > 2 ||
        a.number("--interp-order", 2) != static_cast<double>(o.interp_order))
        throw UsageError("--interp-order must be 0, 1 or 2");
    return o;
}

} // namespace

Command sim_command() {
    return make_command(
        "sim", "simulate a model (compiled on the fly) and write its channels as CSV",
        R"(yamsc sim MODEL.mbd --tmax T --dt DT [--ic name=v,..] [--u name=v,..] [--set name=v,..]
                    [--method rk4|abm4|cvode] [--rtol R] [--atol A] [-o out.csv]
                    [--dt-out DT_OUT] [-v]
                    [--channels all|openfast] [--compare ref.csv] [--plot out.svg]
                    [--plot-channels a,b,..] [--vtk DIR] [--linear [--at name=v,..]]
                    [--aero Cp_Ct_Cq.txt] [--wind V|step:V0:V1:t=T|wind.csv]
                    [--mooring FILE] [--hydro HydroDyn.dat [--sea-state SeaState.dat]]
                    [--controller libdiscon.so [--controller-input DISCON.IN]]
                    [--coupling tight|loose [--interp-order 0|1|2]]
                    [--sid body=file.sid,..] [--external lib.so|file.c|file.cpp])",
        R"(  --tmax T            the end time [s] (required)
  --dt DT             the step (RK4, ABM4) or the output step (CVODE) [s] (required)
  --dt-out DT_OUT     a row every DT_OUT seconds (a multiple of --dt); default every step
  --ic name=v,..      initial values of DOFs and rates (q=v, q'=v) over the `initial` block
  --u name=v,..       constant inputs
  --set name=v,..     parameter values (accept `deg`: --set theta=5deg)
  --sid body=file.sid the shape integrals of a flexible body with `symbolic modes`
  --external LIB      the model's external functions: lib.so, or file.c|file.cpp compiled
  --method M          rk4 (default), abm4 (OpenFAST's ElastoDyn) or cvode (BDF, adaptive)
  --rtol R, --atol A  CVODE's tolerances (1e-8, 1e-10)
  -o out.csv          the CSV: time, the DOFs, their rates, the outputs (default: summary only)
  -v                  progress on stderr
  --channels C        all (default), or openfast: OpenFAST's channel names and units
  --compare ref.csv   the error per channel against a reference table
  --plot out.svg      the channels (with the reference) as SVG
  --plot-channels a,b the channels to plot (default: those compared, or all)
  --vtk DIR           the scene for ParaView at every row: DIR/MODEL.pvd, one
                      DIR/MODEL_NNNNNN.vtp per row and DIR/MODEL.csv (docs/visualization.md)
  --linear            integrate the linear model about the operating point
  --at name=v,..      the operating point of --linear
  --aero FILE         the rotor's data: a Cp/Ct/Cq table (ROSCO's format) for the
                      model's `load rotor_table`, an AeroDyn file for `load blade_elements`
  --wind SPEC         the wind input a load block declares: a speed, step:V0:V1:t=T,
                      or a CSV of time and speed
  --mooring FILE      MAP++'s or MoorDyn's lines for `load mooring` (docs/mooring.md)
  --hydro FILE        a HydroDyn file for the model's `load hydrodyn` (docs/hydrodynamics.md)
  --sea-state FILE    its SeaState file: the waves (still water without)
  --controller LIB    a DISCON controller library called at every step (RK4, ABM4)
  --controller-input F  its input file (accINFILE)
  --coupling C        how load blocks meet the structure in a step: tight (default,
                      evaluated at every stage) or loose (once per step at its end,
                      extrapolated within the next, as OpenFAST's ModCoupling 1)
  --interp-order N    loose coupling's extrapolation: 0 held, 1 linear, 2 quadratic
                      (default, OpenFAST's InterpOrder)
Details: docs/cli.md.
)",
        {{"--tmax",     "--dt",       "--dt-out",       "--ic",         "--u",
          "--set",      "--sid",      "--method",       "-o",           "--rtol",
          "--atol",     "--channels", "--compare",      "--plot",       "--plot-channels",
          "--at",       "--aero",     "--wind",         "--controller", "--controller-input",
          "--external", "--coupling", "--interp-order", "--vtk",        "--mooring",
          "--hydro",    "--sea-state"},
         {"-v", "--linear"}},
        parse_sim, analysis::sim);
}

} // namespace yamsc::cli
