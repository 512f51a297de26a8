// The table of yamsc's commands. A new command is a file in commands/ with its
// options' parser and its entry (make_command), declared in commands/commands.hpp
// and listed here; `yamsc --help` and `yamsc NAME --help` then show it, and
// tests/cli_help checks its help names every option it takes.
#include "cli/command.hpp"
#include "cli/commands/commands.hpp"

#include <cstdio>

namespace yamsc::cli {

const std::vector<Command>& command_table() {
    static const std::vector<Command> table = {
        compile_command(),       check_command(),       eval_command(), sim_command(),
        batch_command(),         batch_merge_command(), lin_command(),  trim_command(),
        from_openfast_command(), rotor_table_command(), sid_command(),  loads_command(),
        turbulence_command(),    dlc_command(),         view_command(), fmu_command(),
    };
    return table;
}

std::string overview_help() {
    std::string text = R"(usage: yamsc COMMAND [options]       yamsc COMMAND --help: what it takes
       yamsc MODEL.mbd -o model.cpp [options]   (yamsc compile)
       yamsc --version | --help | help COMMAND

commands:
)";
    for (const Command& c : command_table()) {
        char line[32];
        std::snprintf(line, sizeof line, "  %-16s", c.name.c_str());
        text += line + c.summary + "\n";
    }
    text += R"(
eval, lin, trim and sim take --external lib.so|file.c|file.cpp: the model's external
functions (a library exporting them, or a source compiled with the model; docs/cli.md).
eval, lin, trim and sim take --sid body=file.sid: the shape integrals of a flexible body
declared with `symbolic modes`, read from a SID file. Values accept `deg`: --set theta_t=5deg.
sim starts from the model's `initial` block (zeros without one); --ic overrides single values.
Exit status: 0 ok, 1 error in the model or its inputs, 2 usage error (also an output that
names an input or another output: nothing is written), 70 internal error.
)";
    return text;
}

} // namespace yamsc::cli
