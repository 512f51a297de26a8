// `yamsc rotor-table`: the rotor block's table as C99, or a table computed with
// AeroDyn's steady BEM from an OpenFAST deck.
#include "analysis/commands.hpp"
#include "analysis/rotor_table_bem.hpp"
#include "cli/commands/commands.hpp"

#include <cmath>
#include <cstdlib>

namespace yamsc::cli {

namespace {

// "first:step:last" or "v1,v2,...": increasing values.
std::vector<double> parse_grid(const std::string& option, const std::string& text) {
    auto number = [&](const std::string& s) {
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (s.empty() || *end != '\0' || !std::isfinite(v))
            throw UsageError(option + ": '" + s + "' is not a number");
        return v;
    };
    std::vector<double> v;
    const auto colon = text.find(':');
    if (colon != std::string::npos) {
        const auto second = text.find(':', colon + 1);
        if (second == std::string::npos)
            throw UsageError(option + " must be first:step:last or a comma list");
        const double first = number(text.substr(0, colon));
        const double step = number(text.substr(colon + 1, second - colon - 1));
        const double last = number(text.substr(second + 1));
        if (!(step > 0) || last < first || (last - first) / step > 10000)
            throw UsageError(option + ": first:step:last needs step > 0 and last >= first");
        for (int i = 0; first + i * step <= last + 1e-9 * step; ++i) v.push_back(first + i * step);
    } else {
        for (const std::string& s : comma_list(text)) v.push_back(number(s));
    }
    for (std::size_t i = 1; i < v.size(); ++i)
        if (!(v[i] > v[i - 1])) throw UsageError(option + " must increase");
    if (v.size() < 2) throw UsageError(option + " needs two or more values");
    return v;
}

driver::RotorTableOptions parse_rotor_table(const Args& a) {
    driver::RotorTableOptions o;
    o.table = a.model();
    o.output = a.get("-o");
    const bool deck = analysis::is_openfast_deck(o.table);
    if (o.output.empty())
        throw UsageError(deck ? "rotor-table needs -o Cp_Ct_Cq.txt"
                              : "rotor-table needs -o rotor_table.c");
    if (a.has("--prefix")) o.prefix = a.get("--prefix");
    for (const char* name : {"--tsr", "--pitch", "--wind", "--azimuths"})
        if (!deck && a.has(name))
            throw UsageError(std::string(name) + " is for a table from a deck (.fst)");
    if (!deck) return o;
    // Without --tsr and --pitch, the grids of ROSCO's NREL 5-MW table.
    o.tsr = parse_grid("--tsr", a.get("--tsr", "2:0.5:14.5"));
    o.pitch_deg = parse_grid("--pitch", a.get("--pitch", "-5:1:30"));
    o.wind = a.number("--wind", o.wind);
    if (!(o.wind > 0)) throw UsageError("--wind must be positive");
    const double azimuths = a.number("--azimuths", o.azimuths);
    if (!(azimuths >= 1 && azimuths <= 360 && azimuths == std::floor(azimuths)))
        throw UsageError("--azimuths must be an integer from 1 to 360");
    o.azimuths = static_cast<int>(azimuths);
    return o;
}

} // namespace

Command rotor_table_command() {
    return make_command(
        "rotor-table", "a Cp/Ct/Cq table as one C99 file, or computed from an OpenFAST deck",
        "yamsc rotor-table Cp_Ct_Cq.txt -o rotor_table.c [--prefix NAME]\n"
        "       yamsc rotor-table DECK.fst -o Cp_Ct_Cq.txt [--tsr A:STEP:B] [--pitch A:STEP:B]\n"
        "                         [--wind V] [--azimuths N]",
        R"(  -o FILE             the C file (required); from a deck, the table in ROSCO's format
  --prefix NAME       of every name in the C file (default rotor_table)
  --tsr LIST          from a deck: tip-speed ratios, A:STEP:B or a comma list
                      (default 2:0.5:14.5, ROSCO's)
  --pitch LIST        from a deck: collective pitch [deg] (default -5:1:30)
  --wind V            from a deck: the wind speed [m/s] (default 11.4)
  --azimuths N        from a deck: azimuths averaged over a blade passage (default 6)
Details: docs/cli.md (Rotor aerodynamics and wind).
)",
        {{"-o", "--prefix", "--tsr", "--pitch", "--wind", "--azimuths"}, {}}, parse_rotor_table,
        analysis::rotor_table);
}

} // namespace yamsc::cli
