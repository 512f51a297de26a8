// `yamsc fmu`: a model packaged as an FMI unit (analysis/fmu_command.cpp).
#include "analysis/commands.hpp"
#include "cli/commands/commands.hpp"

namespace yamsc::cli {

namespace {

using driver::FmiVersion;
using driver::FmuOptions;
using driver::SimMethod;

FmuOptions parse_fmu(const Args& a) {
    FmuOptions o;
    o.model = a.model();
    o.output = a.get("-o");
    if (o.output.empty()) throw UsageError("no output given (-o model.fmu)");
    o.version = choice(a, "--fmi-version", FmiVersion::fmi3,
                       {{"3", FmiVersion::fmi3}, {"2", FmiVersion::fmi2}});
    o.method =
        choice(a, "--method", SimMethod::rk4,
               {{"rk4", SimMethod::rk4}, {"abm4", SimMethod::abm4}, {"cvode", SimMethod::cvode}});
    o.step = a.number("--step", 0);
    if (a.has("--step") && !(o.step > 0)) throw UsageError("--step must be positive");
    o.set = a.assignments("--set");
    o.external = a.get("--external");
    o.aero = a.get("--aero");
    o.depfile = a.get("--depfile");
    o.verbose = a.has("-v");
    return o;
}

} // namespace

Command fmu_command() {
    return make_command(
        "fmu", "package a model as an FMI 3.0 or 2.0 unit (model exchange and co-simulation)",
        R"(yamsc fmu MODEL.mbd -o model.fmu [--fmi-version 3|2] [--method rk4|abm4|cvode]
                    [--step DT] [--set name=v,..] [--external file.c|file.cpp]
                    [--aero Cp_Ct_Cq.txt|AeroDyn15.dat] [--depfile FILE] [-v])",
        R"(  -o FILE             the unit (a ZIP file, conventionally .fmu) (required)
  --fmi-version V     3 (default) or 2: the standard modelDescription.xml follows
  --method M          the co-simulation step's integrator: rk4 (default), abm4 or cvode
  --step DT           its fixed internal step [s] (default 0.001)
  --set name=v,..     the parameters' start values (accept `deg`)
  --external SRC      the model's external functions, a C or C++ source compiled in
  --aero FILE         the rotor's data, as for sim: the Cp/Ct/Cq table of a `load
                      rotor_table`, or the AeroDyn primary file of a `load blade_elements`
                      (with its blade and airfoil files), carried under resources/
                      (the wind is then the unit's input)
  --depfile FILE      a make rule: the unit depends on the model and every file it read
  -v                  progress on stderr
Details: docs/cli.md, docs/packaging.md, docs/fmi.md.
)",
        {{"-o", "--fmi-version", "--method", "--step", "--set", "--external", "--aero",
          "--depfile"},
         {"-v"}},
        parse_fmu, analysis::fmu);
}

} // namespace yamsc::cli
