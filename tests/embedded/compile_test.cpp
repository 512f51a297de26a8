// Every shipped model's C output as a controller's target would build it:
// strict C99 with gcc and clang, in double and in float, and with nothing
// undefined in the object but the math library (no allocation, no I/O, no
// exit) and no writable data (no globals).
#include "embedded/support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <set>
#include <sstream>
#include <vector>

using namespace embedded_test;

namespace {

const std::vector<std::string> math_functions{"sin",   "cos",  "tan",  "asin", "acos",  "atan",
                                              "atan2", "sinh", "cosh", "tanh", "asinh", "acosh",
                                              "atanh", "exp",  "log",  "fabs", "sqrt",  "pow"};

// The math functions the object may call: the double ones, or in float code
// only the float ones (a call of sin in float code computes in double).
std::set<std::string> allowed_symbols(bool single) {
    std::set<std::string> names;
    for (const std::string& f : math_functions) names.insert(single ? f + "f" : f);
    return names;
}

// The symbols `nm -u` lists as undefined in the object.
std::vector<std::string> undefined_symbols(const std::string& object, std::string& log) {
    const std::string listing = object + ".nm";
    if (run("nm -u " + object + " > " + listing + " 2>&1") != 0) {
        log += "nm failed: " + read_file(listing);
        return {"(nm failed)"};
    }
    std::istringstream lines(read_file(listing));
    std::vector<std::string> names;
    std::string kind, name;
    while (lines >> kind >> name) names.push_back(name);
    return names;
}

// The undefined symbols of `object` outside the allowed math functions.
std::vector<std::string> foreign_symbols(const std::string& object, bool single, std::string& log) {
    const std::set<std::string> allowed = allowed_symbols(single);
    std::vector<std::string> foreign;
    for (const std::string& s : undefined_symbols(object, log))
        if (!allowed.count(s)) foreign.push_back(s);
    return foreign;
}

// The sizes of the writable data sections (.data, .bss) of `object`.
long writable_bytes(const std::string& object) {
    const std::string listing = object + ".size";
    if (run("size -A " + object + " > " + listing + " 2>&1") != 0) return -1;
    std::istringstream lines(read_file(listing));
    std::string line;
    long bytes = 0;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string section;
        long size = 0;
        if (words >> section >> size && (section == ".data" || section == ".bss")) bytes += size;
    }
    return bytes;
}

std::string join(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : " ") + n;
    return out;
}

// Strict C99; float code must not compute in double anywhere (a double
// literal or function promotes) nor lose precision to conversions.
std::string flags(bool single) {
    return std::string("-std=c99 -pedantic -Wall -Wextra -Werror -c") +
           (single ? " -Wdouble-promotion -Wfloat-conversion" : "");
}

std::vector<std::string> shipped_models() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(YAMSC_SOURCE_DIR "/models"))
        if (entry.path().extension() == ".mbd") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

TEST_CASE("the symbol check sees allocation, I/O and exit in an object") {
    const std::string dir = scratch_dir("symbol_check");
    write_file(dir + "/leaky.c", "#include <math.h>\n#include <stdio.h>\n#include <stdlib.h>\n"
                                 "double f(double x) {\n"
                                 "    double* p = malloc(sizeof *p);\n"
                                 "    if (!p) exit(1);\n"
                                 "    *p = sin(x);\n    printf(\"%g\\n\", *p);\n"
                                 "    x = *p;\n    free(p);\n    return x;\n}\n"
                                 "int counter;\n");
    REQUIRE(run(std::string(YAMSC_C_COMPILER) + " -std=c99 -c " + dir + "/leaky.c -o " + dir +
                "/leaky.o") == 0);
    std::string log;
    const std::vector<std::string> foreign = foreign_symbols(dir + "/leaky.o", false, log);
    const std::set<std::string> found(foreign.begin(), foreign.end());
    CHECK(found.count("malloc"));
    CHECK(found.count("free"));
    CHECK(found.count("exit"));
    CHECK(found.count("printf"));
    CHECK_FALSE(found.count("sin"));
    // sin is not allowed in float code.
    const std::vector<std::string> in_float = foreign_symbols(dir + "/leaky.o", true, log);
    CHECK(std::find(in_float.begin(), in_float.end(), "sin") != in_float.end());
    CHECK(writable_bytes(dir + "/leaky.o") > 0);
}

TEST_CASE("every shipped model's C builds with gcc and clang, double and float, libm only") {
    const std::string dir = scratch_dir("models");
    const std::vector<std::string> models = shipped_models();
    REQUIRE(models.size() >= 8);
    int objects = 0;
    for (const std::string& model : models) {
        const auto start = std::chrono::steady_clock::now();
        for (const std::string real : {"double", "float"}) {
            const bool single = real == "float";
            const std::string prefix = model + "_" + real;
            std::string log;
            REQUIRE_MESSAGE(generate_c("models/" + model + ".mbd", dir, prefix, real, log), log);
            for (const std::string compiler : {"gcc", "clang"}) {
                const std::string object = dir + "/" + prefix + "." + compiler + ".o";
                const std::string compile_log = object + ".log";
                INFO(model, " --real ", real, " with ", compiler);
                REQUIRE_MESSAGE(run(compiler + " " + flags(single) + " " + dir + "/" + prefix +
                                    ".c -o " + object + " > " + compile_log + " 2>&1") == 0,
                                read_file(compile_log));
                CHECK_MESSAGE(read_file(compile_log).empty(), read_file(compile_log));
                const std::vector<std::string> foreign = foreign_symbols(object, single, log);
                CHECK_MESSAGE(foreign.empty(), "undefined beyond libm: ", join(foreign), log);
                CHECK(writable_bytes(object) == 0);
                ++objects;
            }
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        MESSAGE(model, ": generated and compiled in ", seconds, " s");
    }
    CHECK(objects == 4 * static_cast<int>(models.size()));
}

TEST_CASE("the tangent form's sweeps are float too") {
    // Its internal routines and loops are printed by other code than the
    // unrolled Jacobians; the float warnings catch any double left in them.
    const std::string dir = scratch_dir("tangent");
    for (const std::string model : {"double_pendulum", "nrel5mw_land_2dof"}) {
        std::string log;
        REQUIRE_MESSAGE(
            generate_c("models/" + model + ".mbd", dir, model, "float", log, "--jacobians tangent"),
            log);
        const std::string source = dir + "/" + model + ".c";
        CHECK(read_file(source).find("seed[") != std::string::npos); // a sweep is there
        const std::string object = dir + "/" + model + ".o";
        REQUIRE_MESSAGE(run("gcc " + flags(true) + " " + source + " -o " + object + " > " + object +
                            ".log 2>&1") == 0,
                        read_file(object + ".log"));
        const std::vector<std::string> foreign = foreign_symbols(object, true, log);
        CHECK_MESSAGE(foreign.empty(), "undefined beyond libm: ", join(foreign), log);
    }
}
