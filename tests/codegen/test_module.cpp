// The language-neutral module and the emitted interface: routines and their
// steps, the short mass matrix, shared work computed once, unused arguments,
// model text that cannot inject code, and the cost of a DAG-shaped model.
#include "codegen/emit.hpp"
#include "codegen/module.hpp"
#include "compile_support.hpp"
#include "diag/diagnostics.hpp"
#include "fixtures.hpp"
#include "lower/lower.hpp"

#include <chrono>
#include <doctest/doctest.h>
#include <map>
#include <regex>

using namespace yamsc::codegen;
using namespace codegen_test;

namespace {

std::vector<StepKind> step_kinds(const Routine& r) {
    std::vector<StepKind> kinds;
    for (const Step& s : r.steps) kinds.push_back(s.kind);
    return kinds;
}

/// Function definitions of an emitted C++ source, by name (overloads joined).
std::map<std::string, std::string> function_bodies(const std::string& source) {
    std::map<std::string, std::string> bodies;
    const std::regex head(R"(^void (\w+)\(.*\) \{$)");
    std::istringstream lines(source);
    std::string line, current;
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_match(line, m, head)) {
            current = m[1];
        } else if (line == "}") {
            current.clear();
        } else if (!current.empty()) {
            bodies[current] += line + "\n";
        }
    }
    return bodies;
}

} // namespace

TEST_CASE("the module has its routines with their steps") {
    const Equations eq = double_pendulum();
    const Module m = build_module(eq);
    std::vector<std::string> names;
    for (const Routine& r : m.routines) names.push_back(r.name);
    // The seven nonlinear routines come first, in this order.
    REQUIRE(names.size() >= 7);
    CHECK(std::vector<std::string>(names.begin(), names.begin() + 7) ==
          std::vector<std::string>{"mass_matrix", "forcing", "jacobians", "outputs_from_qdd",
                                   "outputs", "rhs", "rhs_jacobian"});
    // The outputs read no q'': outputs calls outputs_from_qdd with q'' = 0.
    CHECK(step_kinds(m.routine("outputs")) ==
          std::vector<StepKind>{StepKind::evaluate, StepKind::call});
    CHECK(m.routine("outputs").steps.back().call.callee == "outputs_from_qdd");
    CHECK(step_kinds(m.routine("rhs")) ==
          std::vector<StepKind>{StepKind::evaluate, StepKind::factor, StepKind::solve});
    CHECK(step_kinds(m.routine("rhs_jacobian")) ==
          std::vector<StepKind>{StepKind::evaluate, StepKind::factor, StepKind::solve,
                                StepKind::evaluate, StepKind::solve});
    const Step& columns = m.routine("rhs_jacobian").steps.back();
    CHECK(columns.target == "J");
    CHECK(columns.offset == 2 * 4); // the lower nq rows of the 2nq x 2nq J
    CHECK(columns.columns == 4);
    CHECK_THROWS_AS(m.routine("no_such_routine"), yamsc::diag::InternalError);
}

TEST_CASE("the short mass_matrix exists exactly when M depends on q and p only") {
    CHECK(build_module(pendulum()).mass_matrix_short_form);
    CHECK(build_module(double_pendulum()).mass_matrix_short_form);
    const Module pres = build_module(prescribed()); // M = J + m r^2, r an input
    CHECK_FALSE(pres.mass_matrix_short_form);
    const EmittedFiles c = emit_c(pres, {});
    CHECK(c.source.find("void prescribed_mass_matrix_tu(") != std::string::npos);
    CHECK(c.source.find("void prescribed_mass_matrix(") == std::string::npos);
    const EmittedFiles cpp = emit_cpp(build_module(pendulum()), {});
    CHECK(cpp.source.find("void mass_matrix(const double* q, const Params& p, double* M) {") !=
          std::string::npos);
}

TEST_CASE("unused arguments are known and cast to void") {
    const Module m = build_module(pendulum());
    const Routine& forcing = m.routine("forcing");
    CHECK_FALSE(forcing.argument("t")->used);
    CHECK(forcing.argument("qd")->used);
    CHECK(forcing.argument("u")->used);
    CHECK(forcing.argument("p")->used);
    const auto bodies = function_bodies(emit_cpp(m, {}).source);
    CHECK(bodies.at("forcing").find("(void)t;") != std::string::npos);
    CHECK(bodies.at("forcing").find("(void)u;") == std::string::npos);
}

TEST_CASE("each elementary function of a value is evaluated once per function") {
    const Module m = build_module(double_pendulum());
    for (const EmittedFiles& files : {emit_cpp(m, {}), emit_c(m, {})}) {
        const auto bodies = function_bodies(files.source);
        CHECK(bodies.size() >= 6);
        const std::regex call(R"((?:std::)?(?:sin|cos)\([^()]*\))");
        for (const auto& [name, body] : bodies) {
            std::map<std::string, int> seen;
            for (auto it = std::sregex_iterator(body.begin(), body.end(), call);
                 it != std::sregex_iterator(); ++it)
                ++seen[it->str()];
            for (const auto& [text, count] : seen) {
                INFO(name << ": " << text);
                CHECK(count == 1);
            }
        }
        // rhs_jacobian needs sin(x[0]) for F and cos(x[0]) for dF_dq, once each.
        const std::string& jacobian = bodies.count("rhs_jacobian")
                                          ? bodies.at("rhs_jacobian")
                                          : bodies.at("double_pendulum_rhs_jacobian");
        CHECK(occurrences(jacobian, "sin(x[0])") == 1);
        CHECK(occurrences(jacobian, "cos(x[0])") == 1);
    }
}

TEST_CASE("a 60-level self-composition compiles to a small module quickly") {
    const Equations eq = deep_chain(60);
    const auto start = std::chrono::steady_clock::now();
    const Module m = build_module(eq);
    const EmittedFiles files = emit_cpp(m, {});
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    MESSAGE("deep_chain(60): module and C++ in " << seconds * 1e3 << " ms, " << files.source.size()
                                                 << " bytes");
    CHECK(seconds < 2.0);
    CHECK(files.source.size() < 100000);
    const auto bodies = function_bodies(files.source);
    CHECK(occurrences(bodies.at("forcing"), "std::sin(") == 60);
    CHECK(occurrences(bodies.at("forcing"), "std::cos(") == 0);
    CHECK(m.routine("forcing").temporary_count < 200);
}

TEST_CASE("model text cannot break out of comments or strings") {
    Equations eq = pendulum();
    eq.title = "evil */ title\n#error injected by the title";
    eq.source_path = "C:\\models\\pendulum\\";
    eq.params[1].doc = "length \\";
    eq.dofs[0].doc = "angle?\?/"; // a trigraph in C99
    eq.inputs[0].name = "tau\"\\?";
    const Module m = build_module(eq);
    for (const EmittedFiles& f :
         {emit_cpp(m, {"", "pendulum.hpp", "", "--x \"y\"\n#error z"}), emit_c(m, {})}) {
        for (const std::string& text : {f.source, f.header}) {
            CHECK(text.find("\n#error") == std::string::npos);
            CHECK(text.find("\\\n") == std::string::npos);
        }
    }
    CHECK(emit_cpp(m, {}).source.find(R"("tau\"\\\?")") != std::string::npos);
}

TEST_CASE("invalid names and malformed equations are internal errors") {
    const Module m = build_module(pendulum());
    EmitOptions bad_ns;
    bad_ns.namespace_name = "two words";
    CHECK_THROWS_AS(emit_cpp(m, bad_ns), yamsc::diag::InternalError);
    CHECK_THROWS_AS(emit_c(m, bad_ns), yamsc::diag::InternalError);
    EmitOptions nested;
    nested.namespace_name = "models::pendulum";
    CHECK(emit_cpp(m, nested).source.find("namespace models::pendulum {") != std::string::npos);
    CHECK_THROWS_AS(emit_c(m, nested), yamsc::diag::InternalError);
    EmitOptions bad_header;
    bad_header.header_name = "a\"b.hpp";
    CHECK_THROWS_AS(emit_cpp(m, bad_header), yamsc::diag::InternalError);

    // Without the passes, the System has no Jacobians to lower.
    CHECK_THROWS_AS(yamsc::codegen::build_module(yamsc::lower::lower(pendulum())),
                    yamsc::diag::InternalError);
    Equations accelerations_in_F = pendulum();
    accelerations_in_F.F[0] += accelerations_in_F.dofs[0].qdd;
    CHECK_THROWS_AS(build_module(accelerations_in_F), yamsc::diag::InternalError);
    Equations rates_in_M = pendulum();
    rates_in_M.M[0][0] += rates_in_M.dofs[0].qd;
    CHECK_THROWS_AS(build_module(rates_in_M), yamsc::diag::InternalError);
}

TEST_CASE("the header comment documents the model and the cost of each function") {
    const Module m = build_module(pendulum());
    EmitOptions options;
    options.compiler_version = "9.9.9";
    options.command_line = "--lang cpp";
    const std::string text = emit_cpp(m, options).source;
    CHECK(text.rfind("// Generated by yamsc 9.9.9 -- do not edit.\n", 0) == 0);
    CHECK(text.find("// Source: \"tests/pendulum.mbd\"") != std::string::npos);
    CHECK(text.find("// Source digest: \"0123abcd\"") != std::string::npos);
    CHECK(text.find("// Options: \"--lang cpp\"") != std::string::npos);
    CHECK(text.find("\"m\" = (no default: set before use) \"parameter m\"") != std::string::npos);
    CHECK(text.find("\"g\" = 9.807 \"parameter g\"") != std::string::npos);
    CHECK(text.find("u[0] \"tau\" \"joint torque [N m]\"") != std::string::npos);
    // F = tau - m g l sin(theta) - c theta': 2 adds, 4 muls, 1 call.
    CHECK(text.find("//   forcing           2 adds, 4 muls, 0 divs, 1 calls\n") !=
          std::string::npos);
}

TEST_CASE("dump lists the routines, temporaries and solves") {
    const std::string d = dump(build_module(pendulum()));
    CHECK(d.find("module pendulum \"Simple pendulum\"") != std::string::npos);
    CHECK(d.find("mass_matrix short form: yes") != std::string::npos);
    CHECK(d.find("routine rhs_jacobian(t, x, u, p, J)") != std::string::npos);
    CHECK(d.find("    t0 = sin(x[0])") != std::string::npos);
    CHECK(d.find("  factor M = L D L^T  (n = 1)") != std::string::npos);
    CHECK(d.find("  solve M X = J[2..]  (n = 1, 2 columns)") != std::string::npos);
}
