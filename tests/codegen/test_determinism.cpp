// Identical bytes whatever the construction order of the GiNaC objects, and
// in another process (another address layout, so other GiNaC hash orders).
#include "codegen/emit.hpp"
#include "codegen/module.hpp"
#include "compile_support.hpp"
#include "fixtures.hpp"

#include <cstdlib>
#include <doctest/doctest.h>
#include <filesystem>
#include <unistd.h>

using namespace yamsc::codegen;
using namespace codegen_test;

namespace {

std::string everything(const Equations& eq) {
    const Module m = build_module(eq);
    EmitOptions options;
    options.header_name = "model.hpp";
    const EmittedFiles cpp = emit_cpp(m, options);
    options.header_name = "model.h";
    const EmittedFiles c = emit_c(m, options);
    return dump(m) + cpp.source + cpp.header + c.source + c.header;
}

std::string self_path() {
    char buffer[4096];
    const ssize_t n = readlink("/proc/self/exe", buffer, sizeof buffer - 1);
    return n > 0 ? std::string(buffer, static_cast<std::size_t>(n)) : std::string();
}

constexpr const char* child_variable = "YAMSC_CODEGEN_CHILD_OUT";

} // namespace

TEST_CASE("the text does not depend on the order GiNaC objects were made in") {
    const std::string a = everything(double_pendulum(false));
    const std::string b = everything(double_pendulum(true));
    CHECK(a.size() > 1000);
    CHECK(a == b);
    CHECK(everything(deep_chain(40)) == everything(deep_chain(40)));
}

// Run by the next test in child processes; on its own it checks the text is sane.
TEST_CASE("codegen child process: emit the double pendulum") {
    const std::string text = everything(double_pendulum(true));
    CHECK(text.find("namespace double_pendulum {") != std::string::npos);
    if (const char* out = std::getenv(child_variable)) write_file(out, text);
}

TEST_CASE("the text is identical in other processes") {
    const std::string exe = self_path();
    REQUIRE(!exe.empty());
    const std::string dir = scratch_dir("determinism");
    const std::string expected = everything(double_pendulum(false));
    for (int run = 0; run < 2; ++run) {
        const std::string out = dir + "/child" + std::to_string(run) + ".txt";
        const std::string command = std::string(child_variable) + "=" + out + " " + exe +
                                    " --test-case=\"codegen child process*\" > " + dir +
                                    "/child.log 2>&1";
        INFO(command);
        REQUIRE(std::system(command.c_str()) == 0);
        CHECK(read_file(out) == expected);
    }
}
