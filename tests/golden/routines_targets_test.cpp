// The routine table (codegen/routines.hpp) agrees with the C ABI of compiled
// models (runtime/include/yamsc/abi_export.hpp), with the committed generated
// files and with what the loader finds in a compiled library; the export
// targets are found by name and by the extension of -o (driver/targets.hpp).
#include "analysis/jit.hpp"
#include "codegen/routines.hpp"
#include "diag/diagnostics.hpp"
#include "driver/pipeline.hpp"
#include "driver/targets.hpp"

#include <doctest/doctest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace yamsc;
using codegen::RoutineId;

namespace {

const std::string source_dir = YAMSC_SOURCE_DIR;

std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE(in);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool has(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

ir::System double_pendulum() {
    diag::Diagnostics diags;
    driver::FrontEnd fe = driver::run_front_end(source_dir + "/models/double_pendulum.mbd",
                                                driver::Until::jacobians, diags);
    REQUIRE(!diags.has_errors());
    REQUIRE(fe.system);
    return *fe.system;
}

} // namespace

TEST_CASE("every ABI routine of the table is exported by abi_export.hpp, and only those") {
    const std::string abi = read(source_dir + "/runtime/include/yamsc/abi_export.hpp");
    std::set<std::string> macros;
    for (const codegen::RoutineRow& row : codegen::routine_table()) {
        if (!row.abi_symbol) continue;
        macros.insert(row.abi_macro);
        CHECK(has(abi, std::string("#define ") + row.abi_macro + "(NS)"));
        CHECK(has(abi, std::string(row.abi_symbol) + "("));
        CHECK(has(abi, std::string("    ") + row.abi_macro + "(NS)")); // in YAMSC_EXPORT_MODEL
    }
    CHECK(macros.size() == 10);
    // Every per-routine macro of the header is a row of the table.
    for (std::size_t at = abi.find("#define YAMSC_EXPORT_"); at != std::string::npos;
         at = abi.find("#define YAMSC_EXPORT_", at + 1)) {
        const std::size_t start = at + 8, open = abi.find('(', start);
        const std::string macro = abi.substr(start, open - start);
        if (macro == "YAMSC_EXPORT_MODEL_INFO" || macro == "YAMSC_EXPORT_MODEL" ||
            macro == "YAMSC_EXPORT_CONSTRAINED_MODEL")
            continue;
        CHECK_MESSAGE(macros.count(macro) == 1, macro);
    }
}

TEST_CASE("the generated golden files define every routine of the table") {
    const std::string cpp = read(source_dir + "/generated/double_pendulum.hpp");
    const std::string c = read(source_dir + "/generated/double_pendulum.h");
    for (const codegen::RoutineRow& row : codegen::routine_table()) {
        if (row.id == RoutineId::linear_sensitivities) continue;       // only with --sensitivities
        if (codegen::constraint_routines().contains(row.id)) continue; // only with constraints
        CHECK_MESSAGE(has(cpp, std::string("void ") + row.name + "("), row.name);
        CHECK_MESSAGE(has(c, std::string("void double_pendulum_") + row.name + "("), row.name);
    }
}

TEST_CASE("the JIT exports the routines asked for, and the loader finds exactly those") {
    const ir::System s = double_pendulum();
    const std::string only_outputs = analysis::shared_model_source(s, {RoutineId::outputs});
    // rhs always: the loader needs it.
    CHECK(has(only_outputs, "\nYAMSC_EXPORT_RHS(double_pendulum)\n"));
    CHECK(has(only_outputs, "\nYAMSC_EXPORT_OUTPUTS(double_pendulum)\n"));
    CHECK(!has(only_outputs, "YAMSC_EXPORT_JACOBIANS(double_pendulum)"));
    CHECK_THROWS_AS(analysis::shared_model_source(s, {RoutineId::linear}), std::invalid_argument);

    char folder[] = "/tmp/yamsc_routines_XXXXXX";
    REQUIRE(mkdtemp(folder));
    analysis::JitOptions o;
    o.cache_dir = folder;
    const auto library = analysis::load_compiled_model(s, o);
    std::string found;
    for (const std::string& r : library->routines()) found += (found.empty() ? "" : ", ") + r;
    // This model has no constraints: their routines are not compiled.
    CHECK(found ==
          codegen::routine_names(codegen::abi_routines().without(codegen::constraint_routines())));
    REQUIRE(std::system(("rm -rf " + std::string(folder)).c_str()) == 0);
}

TEST_CASE("export targets are found by --lang and by the extension of -o") {
    using driver::Language;
    REQUIRE(driver::target_for_extension("cpp"));
    CHECK(driver::target_for_extension("cpp")->language == Language::cpp);
    CHECK(driver::target_for_extension("hpp")->language == Language::cpp);
    CHECK(driver::target_for_extension("c")->language == Language::c);
    CHECK(driver::target_for_extension("h")->language == Language::c);
    CHECK(driver::target_for_extension("tex")->language == Language::latex);
    CHECK(driver::target_for_extension("f90") == nullptr);
    CHECK(driver::target_for_extension("") == nullptr);
    CHECK(driver::target_named("latex") == &driver::target(Language::latex));
    CHECK(driver::target_named("fortran") == nullptr);
    CHECK(driver::target_names("|") == "cpp|c|latex");
    // One target per language and per extension.
    std::set<std::string> extensions;
    std::set<Language> languages;
    for (const driver::Target* t : driver::targets()) {
        CHECK(languages.insert(t->language).second);
        CHECK(&driver::target(t->language) == t);
        for (const std::string& e : t->extensions) CHECK_MESSAGE(extensions.insert(e).second, e);
    }
    // Only C takes --real float and a single identifier as its namespace.
    CHECK(driver::target(Language::c).single_precision);
    CHECK(!driver::target(Language::c).nested_namespaces);
    CHECK(!driver::target(Language::cpp).single_precision);
    CHECK(!driver::target(Language::latex).header);
}
