// yamsc: the command line. Finds the command in the table (command_table.cpp),
// prints its help or runs it, and maps errors to exit statuses: 0 success,
// 1 user error, 2 usage error, 70 internal error.
#include "cli/command.hpp"
#include "diag/diagnostics.hpp"

#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

namespace {

using yamsc::cli::Command;
using yamsc::cli::UsageError;

/// A command found on the command line, and where its arguments start.
struct Found {
    const Command* command = nullptr;
    int first_argument = 0;
};

/// The command named by argv[at..]: a subcommand's two words ("batch merge") before one.
Found find_command(int argc, char** argv, int at) {
    if (at >= argc) return {};
    const std::string one = argv[at];
    const std::string two = at + 1 < argc ? one + " " + argv[at + 1] : "";
    for (const Command& c : yamsc::cli::command_table())
        if (!two.empty() && c.name == two) return {&c, at + 2};
    for (const Command& c : yamsc::cli::command_table())
        if (c.name == one) return {&c, at + 1};
    return {};
}

const Command& command_named(const std::string& name) {
    for (const Command& c : yamsc::cli::command_table())
        if (c.name == name) return c;
    throw yamsc::diag::InternalError("no command '" + name + "' in the table");
}

std::vector<std::string> command_names() {
    std::vector<std::string> names;
    for (const Command& c : yamsc::cli::command_table()) names.push_back(c.name);
    return names;
}

/// A first word that is no command and no file but close to a command's name
/// is a misspelt command, not a model to compile.
void reject_misspelt_command(const std::string& word) {
    if (word.empty() || word[0] == '-') return;
    std::error_code ec;
    if (std::filesystem::exists(word, ec)) return;
    const std::string hint = yamsc::diag::did_you_mean(word, command_names());
    if (!hint.empty()) throw UsageError("unknown command '" + word + "'" + hint);
}

void print_help(const Command& c) {
    std::cout << "usage: " << c.usage << "\n" << c.summary << ".\n\n" << c.help;
}

bool asks_for_help(int argc, char** argv, int first) {
    for (int i = first; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") return true;
    }
    return false;
}

/// Runs the command line; `current` is the command once known (its usage goes
/// with a usage error).
int run(int argc, char** argv, const Command*& current) {
    if (argc < 2) throw UsageError("no command given");
    const std::string first = argv[1];
    if (first == "--help" || first == "-h") {
        std::cout << yamsc::cli::overview_help();
        return 0;
    }
    if (first == "--version") {
        std::cout << "yamsc " << YAMSC_VERSION << "\n";
        return 0;
    }
    if (first == "help") {
        if (argc == 2) {
            std::cout << yamsc::cli::overview_help();
            return 0;
        }
        const Found f = find_command(argc, argv, 2);
        if (!f.command || f.first_argument != argc)
            throw UsageError("help: unknown command '" + std::string(argv[2]) + "'" +
                             yamsc::diag::did_you_mean(argv[2], command_names()));
        print_help(*f.command);
        return 0;
    }
    Found f = find_command(argc, argv, 1);
    if (!f.command) {
        reject_misspelt_command(first);
        f = {&command_named("compile"), 1}; // `yamsc MODEL.mbd -o ..`
    }
    current = f.command;
    if (asks_for_help(argc, argv, f.first_argument)) {
        print_help(*f.command);
        return 0;
    }
    return f.command->run(yamsc::cli::Args(argc, argv, f.first_argument, f.command->options));
}

} // namespace

int main(int argc, char** argv) {
    const Command* current = nullptr;
    try {
        return run(argc, argv, current);
    } catch (const UsageError& e) {
        std::cerr << "yamsc: usage error: " << e.what() << "\n";
        if (current)
            std::cerr << "usage: " << current->usage << "\n(yamsc " << current->name
                      << " --help: its options)\n";
        else
            std::cerr << yamsc::cli::overview_help();
        return 2;
    } catch (const yamsc::diag::UserError& e) {
        std::cerr << "yamsc: error: " << e.what() << "\n";
        return 1;
    } catch (const yamsc::diag::InternalError& e) {
        std::cerr << "yamsc: internal error: " << e.what()
                  << "\nThis is a bug in yamsc, not in your model: please report it.\n";
        return 70;
    } catch (const std::exception& e) {
        std::cerr << "yamsc: error: " << e.what() << "\n";
        return 1;
    }
}
