// The passes' order is checked, not remembered: each pass records itself on
// the System and refuses to run before what it needs or after what it must
// precede (passes/pass_order.hpp); the pipeline runs them in that order.
#include "diag/diagnostics.hpp"
#include "ir/graph.hpp"
#include "ir/system.hpp"
#include "passes/pass_order.hpp"
#include "passes/passes.hpp"
#include "passes/pipeline.hpp"
#include "passes/taylor.hpp"
#include "two_dof_system.hpp"

#include <doctest/doctest.h>

#include <functional>
#include <string>
#include <vector>

using namespace yamsc::ir;
using ir_test::two_dof_system;
namespace passes = yamsc::passes;
using yamsc::diag::InternalError;

namespace {

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InternalError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("the pass table is in the order of ir::Pass and names what each pass adds") {
    for (std::size_t i = 0; i < pass_count; ++i) {
        const passes::PassInfo& info = passes::pass_info(static_cast<Pass>(i));
        CHECK(static_cast<std::size_t>(info.pass) == i);
        CHECK(std::string(info.adds).size() > 0);
        // No pass needs one it must precede.
        CHECK(info.needs.both(info.before).empty());
    }
}

TEST_CASE("a pass run before what it needs throws and derives nothing") {
    System s = two_dof_system();
    const std::string message = message_of([&] { passes::parameter_derivatives(s, {0}); });
    CHECK(message.find("parameter_derivatives") != std::string::npos);
    CHECK(message.find("needs derive_jacobians") != std::string::npos);
    CHECK(s.sensitivities.empty());
    CHECK(s.passes.empty());
    System e = two_dof_system();
    CHECK_THROWS_AS(passes::external_jacobians(e), InternalError);
}

TEST_CASE("a pass run after one it must precede throws") {
    System s = two_dof_system();
    passes::derive_jacobians(s);
    CHECK(s.passes == PassSet{Pass::derive_jacobians});
    // approx replaces M and F: after the Jacobians it would leave them stale.
    const std::string message = message_of([&] {
        passes::approximate(s, {{SymbolKind::q, 0}}, 1);
    });
    CHECK(message.find("must run before derive_jacobians") != std::string::npos);
    CHECK(s.exact_F.empty());
    CHECK_THROWS_AS(passes::separate_externals(s), InternalError);
    // And no pass but approximate runs twice.
    CHECK_THROWS_AS(passes::derive_jacobians(s), InternalError);
}

TEST_CASE("approximate repeats, one run per group, before the derivatives") {
    System s = two_dof_system();
    passes::approximate(s, {{SymbolKind::q, 0}}, 1);
    passes::approximate(s, {{SymbolKind::q, 1}}, 2);
    passes::derive_jacobians(s);
    CHECK(s.passes == PassSet{Pass::approximate, Pass::derive_jacobians});
    CHECK(s.exact_F.size() == 2);
}

TEST_CASE("the pipeline runs the passes in order and records each") {
    System s = two_dof_system();
    passes::PassPlan plan;
    plan.approximations.push_back({{{SymbolKind::q, 0}}, 1});
    plan.derivatives = passes::PassPlan::Derivatives::unrolled;
    plan.sensitivity_params = {0};
    std::vector<Pass> order;
    passes::run_pipeline(s, plan, [&](Pass p) { order.push_back(p); });
    CHECK(order == std::vector<Pass>{Pass::approximate, Pass::derive_jacobians,
                                     Pass::output_jacobians, Pass::parameter_derivatives});
    CHECK(s.passes == PassSet{Pass::approximate, Pass::derive_jacobians, Pass::output_jacobians,
                              Pass::parameter_derivatives});
    REQUIRE(s.sensitivities.size() == 1);
    CHECK(s.C.size() == 1);

    // Sensitivities need the unrolled Jacobians: a plan asking otherwise is refused.
    System t = two_dof_system();
    plan.approximations.clear();
    plan.derivatives = passes::PassPlan::Derivatives::tangent;
    CHECK_THROWS_AS(passes::run_pipeline(t, plan), InternalError);
}

TEST_CASE("an approx group that cannot be expanded is reported with its index") {
    System s = two_dof_system();
    Graph& g = s.graph;
    // 1/q1 has no expansion about q1 = 0.
    s.F[1] = g.mul({{g.symbol({SymbolKind::q, 1}), -1.0}}, 1.0);
    passes::PassPlan plan;
    plan.approximations.push_back({{{SymbolKind::q, 0}}, 1});
    plan.approximations.push_back({{{SymbolKind::q, 1}}, 1});
    try {
        passes::run_pipeline(s, plan);
        FAIL("expected NotExpandable");
    } catch (const passes::NotExpandable& x) {
        CHECK(x.group == 1);
    }
}
