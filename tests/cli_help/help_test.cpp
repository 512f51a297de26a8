// `yamsc NAME --help` for every command of the table (compiler/cli/command_table.cpp):
// exit 0, the command's synopsis, and a description of every option it takes;
// `yamsc --help` lists the table, and a misspelt command is named with a suggestion.
#include "cli/command.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <cctype>
#include <string>

namespace {

struct Run {
    int status;
    std::string out, err;
};

Run run_yamsc(const std::string& arguments) {
    const std::string dir = test_support::scratch_dir("cli_help", "run");
    const int status = test_support::exit_status(std::string(YAMSC_EXE) + " " + arguments + " >" +
                                                 dir + "/out 2>" + dir + "/err");
    return {status, test_support::read_file(dir + "/out"), test_support::read_file(dir + "/err")};
}

/// `option` in `text` as a word of its own: not a part of a longer option.
bool names_option(const std::string& text, const std::string& option) {
    for (auto at = text.find(option); at != std::string::npos; at = text.find(option, at + 1)) {
        const char before = at == 0 ? ' ' : text[at - 1];
        const std::size_t end = at + option.size();
        const char after = end < text.size() ? text[end] : ' ';
        if ((before == ' ' || before == '[' || before == '|') &&
            !(std::isalnum(static_cast<unsigned char>(after)) || after == '-' || after == '_'))
            return true;
    }
    return false;
}

} // namespace

TEST_CASE("every command's --help exits 0 and describes each of its options") {
    const auto& table = yamsc::cli::command_table();
    REQUIRE(table.size() >= 11);
    for (const yamsc::cli::Command& c : table) {
        CAPTURE(c.name);
        const Run r = run_yamsc(c.name + " --help");
        CHECK(r.status == 0);
        CHECK(r.err.empty());
        CHECK(r.out.rfind("usage: " + c.usage + "\n" + c.summary + ".\n\n", 0) == 0);
        // The option descriptions: what follows the synopsis and the summary.
        const auto descriptions = r.out.find("\n\n");
        REQUIRE(descriptions != std::string::npos);
        const std::string described = r.out.substr(descriptions);
        const std::size_t options = c.options.valued.size() + c.options.flags.size();
        CHECK(options > 0);
        for (const auto* names : {&c.options.valued, &c.options.flags})
            for (const std::string& option : *names) {
                CAPTURE(option);
                CHECK(names_option(c.usage, option));
                CHECK(names_option(described, option));
            }
        CHECK(run_yamsc(c.name + " -h").out == r.out);
        CHECK(run_yamsc("help " + c.name).out == r.out);
    }
}

TEST_CASE("a command's --help wins over its other arguments") {
    const Run r = run_yamsc("lin missing.mbd --at theta=1 --help");
    CHECK(r.status == 0);
    CHECK(names_option(r.out, "--mbc3"));
    CHECK(names_option(r.out, "--sweep"));
    CHECK(r.out.find("usage: yamsc lin MODEL.mbd") == 0);
    CHECK(run_yamsc("batch merge --help").out.find("usage: yamsc batch merge OUTDIR...") == 0);
}

TEST_CASE("yamsc --help lists every command of the table with its summary") {
    const Run r = run_yamsc("--help");
    CHECK(r.status == 0);
    for (const yamsc::cli::Command& c : yamsc::cli::command_table()) {
        CAPTURE(c.name);
        CHECK(r.out.find("  " + c.name + " ") != std::string::npos);
        CHECK(r.out.find(c.summary + "\n") != std::string::npos);
    }
    CHECK(run_yamsc("help").out == r.out);
}

TEST_CASE("a misspelt command is a usage error with a suggestion; a usage error shows its usage") {
    Run r = run_yamsc("simm model.mbd --tmax 1 --dt 0.1");
    CHECK(r.status == 2);
    CHECK(r.err.find("yamsc: usage error: unknown command 'simm' (did you mean 'sim'?)") == 0);
    r = run_yamsc("help lni");
    CHECK(r.status == 2);
    CHECK(r.err.find("help: unknown command 'lni'") != std::string::npos);
    r = run_yamsc("sim x.mbd --tmax 1");
    CHECK(r.status == 2);
    CHECK(r.err.find("yamsc: usage error: sim needs --tmax and --dt\nusage: yamsc sim MODEL.mbd") ==
          0);
    CHECK(r.err.find("(yamsc sim --help: its options)") != std::string::npos);
}
