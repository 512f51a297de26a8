// `yamsc rotor-table`: the rotor block's table as C99.
#include "analysis/commands.hpp"
#include "cli/commands/commands.hpp"

namespace yamsc::cli {

namespace {

driver::RotorTableOptions parse_rotor_table(const Args& a) {
    driver::RotorTableOptions o;
    o.table = a.model();
    o.output = a.get("-o");
    if (o.output.empty()) throw UsageError("rotor-table needs -o rotor_table.c");
    if (a.has("--prefix")) o.prefix = a.get("--prefix");
    return o;
}

} // namespace

Command rotor_table_command() {
    return make_command("rotor-table", "a Cp/Ct/Cq table and its interpolation as one C99 file",
                        "yamsc rotor-table Cp_Ct_Cq.txt -o rotor_table.c [--prefix NAME]",
                        R"(  -o FILE             the C file (required)
  --prefix NAME       of every name in the file (default rotor_table)
Details: docs/cli.md (Rotor aerodynamics and wind).
)",
                        {{"-o", "--prefix"}, {}}, parse_rotor_table, analysis::rotor_table);
}

} // namespace yamsc::cli
