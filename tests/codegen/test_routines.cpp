// The routine table (codegen/routines.hpp): one row per function of the
// generated API, in the order of RoutineId; the module's public routines carry
// their row's id, name and signature; a module is cut down by a set of ids; and
// code generation refuses a System whose passes have not run.
#include "codegen/module.hpp"
#include "codegen/routines.hpp"
#include "codegen/symbol_binding.hpp"
#include "diag/diagnostics.hpp"
#include "fixtures.hpp"
#include "lower/lower.hpp"

#include <doctest/doctest.h>
#include <set>
#include <string>

using namespace yamsc::codegen;
using namespace codegen_test;

TEST_CASE("the routine table has one row per RoutineId, in order, with distinct names") {
    std::set<std::string> names;
    for (std::size_t i = 0; i < routine_count; ++i) {
        const RoutineRow& row = routine_table()[i];
        CHECK(static_cast<std::size_t>(row.id) == i);
        CHECK(names.insert(row.name).second);
        CHECK(routine_named(row.name) == row.id);
        // A routine in the ABI has its symbol and export macro, named after it.
        CHECK((row.abi_symbol == nullptr) == (row.abi_macro == nullptr));
        if (row.abi_symbol) CHECK(std::string(row.abi_symbol) == "yamsc_" + std::string(row.name));
    }
    CHECK(!routine_named("inner_rhs"));
    CHECK(routine_names(abi_routines()) ==
          "rhs, rhs_jacobian, mass_matrix, forcing, jacobians, outputs, constraints, "
          "constraint_matrix, constraint_bias, constraint_jacobians");
    CHECK(routine_names(constraint_routines()) ==
          "constraints, constraint_matrix, constraint_bias, constraint_jacobians");
}

TEST_CASE("the module's public routines are the table's, with its signatures") {
    const Module m = build_module(double_pendulum());
    int public_routines = 0;
    for (const Routine& r : m.routines) {
        if (r.internal) {
            CHECK(!r.id);
            continue;
        }
        ++public_routines;
        REQUIRE(r.id);
        CHECK(r.name == routine_name(*r.id));
        const RoutineBuilder::Signature s = api_signature(*r.id);
        REQUIRE(r.arguments.size() == s.arguments.size());
        for (std::size_t i = 0; i < s.arguments.size(); ++i)
            CHECK(r.arguments[i].name == s.arguments[i].name);
        CHECK(&m.routine(*r.id) == &r);
    }
    // Everything but the sensitivities and the operating point (added apart) and
    // the routines of constraints (this model has none).
    CHECK(public_routines == static_cast<int>(routine_count) - 6);
    CHECK_THROWS_AS(m.routine(RoutineId::operating_point), yamsc::diag::InternalError);
}

TEST_CASE("keep_routines keeps the set asked for and what it calls") {
    Module m = build_module(double_pendulum());
    keep_routines(m, {RoutineId::outputs, RoutineId::rhs});
    std::set<std::string> kept;
    for (const Routine& r : m.routines) kept.insert(r.name);
    // outputs calls outputs_from_qdd (docs/generated-api.md).
    CHECK(kept.count("rhs") == 1);
    CHECK(kept.count("outputs") == 1);
    CHECK(kept.count("jacobians") == 0);
    CHECK(kept.count("linear") == 0);
    Module without_linear = build_module(double_pendulum(), [] {
        Options o;
        o.linear_model = false;
        return o;
    }());
    CHECK_THROWS_AS(keep_routines(without_linear, {RoutineId::state_space}),
                    yamsc::diag::InternalError);
}

TEST_CASE("code generation needs the passes its routines read") {
    const yamsc::ir::System lowered = yamsc::lower::lower(double_pendulum());
    // No Jacobians derived: jacobians and rhs_jacobian have nothing to read.
    try {
        (void)build_module(lowered);
        FAIL("expected InternalError");
    } catch (const yamsc::diag::InternalError& e) {
        CHECK(std::string(e.what()).find("needs a pass that has not run") != std::string::npos);
    }
    // Sensitivities need parameter_derivatives, which system_of does not run.
    Options o;
    o.sensitivity_params = {"g"};
    try {
        (void)build_module(double_pendulum(), o);
        FAIL("expected InternalError");
    } catch (const yamsc::diag::InternalError& e) {
        CHECK(std::string(e.what()).find("linear_sensitivities needs a pass") != std::string::npos);
    }
}
