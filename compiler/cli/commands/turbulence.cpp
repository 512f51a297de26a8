// `yamsc turbulence`: IEC 61400-1 Ed. 3 Kaimal turbulence as a TurbSim .bts file.
#include "analysis/commands.hpp"
#include "cli/commands/commands.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>

namespace yamsc::cli {

namespace {

double positive(const Args& a, const std::string& name) {
    const double v = a.number(name, 0);
    if (!(v > 0)) throw UsageError(name + " must be positive");
    return v;
}

int count(const std::string& option, const std::string& text) {
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || v < 2 || v > 1000)
        throw UsageError(option + ": '" + text + "' is not a count from 2 to 1000");
    return static_cast<int>(v);
}

driver::TurbulenceOptions parse_turbulence(const Args& a) {
    driver::TurbulenceOptions o;
    if (a.positionals().size() > 1) throw UsageError("turbulence takes one TurbSim input file");
    if (!a.positionals().empty()) o.input = a.positionals().front();
    o.output = a.get("-o");
    if (o.output.empty()) throw UsageError("turbulence needs -o FILE.bts");
    using C = driver::TurbulenceCharacteristicOption;
    if (a.has("--class")) {
        const std::string c = a.get("--class");
        if (c == "A" || c == "B" || c == "C") {
            o.characteristic = c == "A" ? C::A : c == "B" ? C::B : C::C;
        } else {
            o.characteristic = C::percent;
            o.intensity_percent = positive(a, "--class");
        }
    }
    using M = driver::TurbulenceModelOption;
    if (a.has("--model"))
        o.model =
            choice(a, "--model", M::ntm,
                   {{"NTM", M::ntm}, {"1ETM", M::etm1}, {"2ETM", M::etm2}, {"3ETM", M::etm3}});
    using P = driver::TurbulenceProfileOption;
    if (a.has("--profile"))
        o.profile =
            choice(a, "--profile", P::power_law, {{"PL", P::power_law}, {"LOG", P::logarithmic}});
    if (a.has("--speed")) o.speed = positive(a, "--speed");
    if (a.has("--hub-height")) o.hub_height = positive(a, "--hub-height");
    if (a.has("--ref-height")) o.ref_height = positive(a, "--ref-height");
    if (a.has("--grid")) {
        const std::string g = a.get("--grid");
        const auto x = g.find('x');
        if (x == std::string::npos) throw UsageError("--grid must be NYxNZ, e.g. 15x15");
        o.ny = count("--grid", g.substr(0, x));
        o.nz = count("--grid", g.substr(x + 1));
    }
    if (a.has("--size")) {
        const std::string s = a.get("--size");
        const auto x = s.find('x');
        o.width = driver::parse_value(s.substr(0, x), "--size");
        o.height =
            x == std::string::npos ? *o.width : driver::parse_value(s.substr(x + 1), "--size");
        if (!(*o.width > 0 && *o.height > 0)) throw UsageError("--size must be positive");
    }
    if (a.has("--dt")) o.time_step = positive(a, "--dt");
    if (a.has("--time")) o.time = positive(a, "--time");
    if (a.has("--seed")) {
        const double seed = a.number("--seed", 0);
        if (seed != std::floor(seed) || std::abs(seed) > std::numeric_limits<std::int32_t>::max())
            throw UsageError("--seed must be an integer of 32 bits");
        o.seed = static_cast<std::int64_t>(seed);
    }
    if (a.has("--shear")) {
        o.shear = a.number("--shear", 0);
        if (!(std::abs(*o.shear) <= 10)) throw UsageError("--shear must be a power-law exponent");
    }
    if (a.has("--roughness")) o.roughness = positive(a, "--roughness");
    if (a.has("--scale")) {
        const double scale = a.number("--scale", 0);
        if (scale != 0 && scale != 1 && scale != 2) throw UsageError("--scale must be 0, 1 or 2");
        o.scale = static_cast<int>(scale);
    }
    o.periodic = a.has("--periodic");
    return o;
}

} // namespace

Command turbulence_command() {
    return make_command(
        "turbulence", "IEC Kaimal turbulence (TurbSim's IECKAI) as a TurbSim .bts wind file",
        "yamsc turbulence [INPUT.inp] -o FILE.bts [--class A|B|C|TI] [--model NTM|1ETM|2ETM|3ETM]\n"
        "                 [--speed V] [--hub-height H] [--ref-height H] [--grid NYxNZ]\n"
        "                 [--size W[xH]] [--dt S] [--time S] [--seed N] [--profile PL|LOG]\n"
        "                 [--shear A] [--roughness Z0] [--scale 0|1|2] [--periodic]",
        R"(  INPUT               a TurbSim input file (TurbModel IECKAI); each option replaces its entry
  -o FILE             the .bts file (required); never one of the inputs
  --class C           IECturbc: A, B, C, or the turbulence intensity in percent
  --model M           IEC_WindType: NTM (default), or the extreme model of turbine class 1-3
  --speed V           URef, the mean speed at the reference height [m/s]
  --hub-height H      HubHt [m]
  --ref-height H      RefHt [m] (without INPUT: the hub height)
  --grid NYxNZ        NumGrid_Y x NumGrid_Z points
  --size W[xH]        GridWidth x GridHeight [m] (one value: square)
  --dt S              TimeStep [s] (without INPUT: 0.05)
  --time S            AnalysisTime and UsableTime [s] (without INPUT: 600)
  --seed N            RandSeed1 (without INPUT: 1); yamsc's random phases are not TurbSim's:
                      the same seed gives another realisation than TurbSim
  --profile P         WindProfileType: PL (power law, default) or LOG (neutral log law)
  --shear A           PLExp, the power-law exponent (default 0.2)
  --roughness Z0      Z0, the log law's roughness length [m] (default 0.03)
  --scale N           ScaleIEC: 0 none (default), 1 the hub's factor everywhere, 2 each point's
  --periodic          UsableTime ALL: a periodic field of the FFT's length
Without INPUT, --class, --speed, --hub-height, --grid and --size are required.
Unsupported entries of INPUT warn at their line. Details: docs/turbulence.md.
)",
        {{"-o", "--class", "--model", "--speed", "--hub-height", "--ref-height", "--grid", "--size",
          "--dt", "--time", "--seed", "--profile", "--shear", "--roughness", "--scale"},
         {"--periodic"}},
        parse_turbulence, analysis::turbulence);
}

} // namespace yamsc::cli
