#pragma once
// One command of `yamsc`: its name, what it does in one line, its help, the
// options it takes, and how it runs: the arguments parsed into the typed
// options of driver/commands.hpp, then the library function called with them.
// The table of every command is command_table.cpp.
#include "cli/args.hpp"

#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace yamsc::cli {

struct Command {
    std::string name;    // as typed: "sim", or "batch merge" for a subcommand
    std::string summary; // one line, for `yamsc --help`
    std::string usage;   // the synopsis, printed with a usage error too
    std::string help;    // one line or more per option, for `yamsc NAME --help`
    OptionNames options;
    /// Parses the arguments after the name and runs the command: its exit status.
    std::function<int(const Args&)> run;
};

/// An entry from its parts: `parse` builds the options, `run` is the command
/// (driver/commands.hpp, analysis/commands.hpp, openfast/from_openfast.hpp).
template <class Options>
Command make_command(std::string name, std::string summary, std::string usage, std::string help,
                     OptionNames options, Options (*parse)(const Args&),
                     int (*run)(const Options&, std::ostream&, std::ostream&)) {
    return {std::move(name),
            std::move(summary),
            std::move(usage),
            std::move(help),
            std::move(options),
            [parse, run](const Args& a) { return run(parse(a), std::cout, std::cerr); }};
}

/// Every command, in the order `yamsc --help` lists them.
const std::vector<Command>& command_table();

/// `yamsc --help`: the commands of the table and what every command shares.
std::string overview_help();

} // namespace yamsc::cli
