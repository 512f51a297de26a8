// `yamsc from-openfast`: an OpenFAST deck as a model.
#include "openfast/from_openfast.hpp"
#include "cli/commands/commands.hpp"

namespace yamsc::cli {

namespace {

using driver::FromOpenFastOptions;

FromOpenFastOptions parse_from_openfast(const Args& a) {
    FromOpenFastOptions o;
    o.deck = a.model();
    o.output = a.get("-o");
    o.cp_table = a.get("--cp-table");
    if (const std::string aero = a.get("--aero"); aero == "table")
        o.aero = driver::RotorAero::table;
    else if (!aero.empty() && aero != "blade-elements")
        throw UsageError("--aero takes blade-elements or table, not '" + aero + "'");
    if (o.output.empty()) throw UsageError("from-openfast needs -o model.mbd");
    for (const std::string& item : comma_list(a.get("--dofs"))) {
        const auto eq = item.find('=');
        const std::string value = eq == std::string::npos ? "" : item.substr(eq + 1);
        if (eq == std::string::npos || (value != "on" && value != "off"))
            throw UsageError("--dofs takes NAME=on|off items (e.g. GenDOF=off), not '" + item +
                             "'");
        o.dofs.emplace_back(item.substr(0, eq), value == "on");
    }
    return o;
}

} // namespace

Command from_openfast_command() {
    return make_command("from-openfast",
                        "an OpenFAST deck (ElastoDyn, or a full .fst) as a .mbd model",
                        "yamsc from-openfast ELASTODYN.dat|DECK.fst [--dofs NAME=on|off,..] "
                        "[--aero blade-elements|table] [--cp-table FILE] -o model.mbd",
                        R"(  -o model.mbd        the model (required)
  --dofs NAME=on|off  ElastoDyn's DOF flags switched (e.g. GenDOF=off)
  --aero blade-elements|table
                      AeroDyn as its blade elements on the flexible blades (the
                      default; a rotor without blade DOFs gets the table), or as
                      the quasi-steady rotor of a Cp/Ct/Cq table
  --cp-table FILE     the table rotor's Cp/Ct/Cq table (default: the controller's)
Details: docs/openfast.md.
)",
                        {{"--dofs", "-o", "--cp-table", "--aero"}, {}}, parse_from_openfast,
                        openfast::from_openfast);
}

} // namespace yamsc::cli
