// Canonical value numbering: equal structures share one number, normal forms
// are unique, and importing a shared DAG costs its size, not its tree size.
#include "diag/diagnostics.hpp"
#include "fixtures.hpp"
#include "ir/graph.hpp"
#include "lower/from_ginac.hpp"

#include <chrono>
#include <doctest/doctest.h>

using namespace yamsc::ir;
using codegen_test::Equations;
using yamsc::lower::GinacImporter;

TEST_CASE("structurally equal expressions get one value number") {
    const Equations eq = codegen_test::pendulum();
    const GiNaC::ex q = eq.dofs[0].q, m = eq.params[0].sym, l = eq.params[1].sym;
    Graph g;
    GinacImporter importer(g, eq);
    // Two separately built GiNaC trees of the same value.
    const GiNaC::ex e1 = sin(q) * (m + l) - 3 * pow(m, 2);
    const GiNaC::ex e2 = (l + m) * sin(q) - pow(m, 2) * 3;
    CHECK(&GiNaC::ex_to<GiNaC::basic>(e1) != &GiNaC::ex_to<GiNaC::basic>(e2));
    CHECK(importer.import(e1) == importer.import(e2));
    CHECK(importer.import(sin(q)) != importer.import(cos(q)));
    CHECK(importer.import(m - l) != importer.import(l - m));
}

TEST_CASE("symbol look-ups do not disturb the memo (GiNaC re-points compared handles)") {
    const Equations eq = codegen_test::pendulum();
    Graph g;
    GinacImporter importer(g, eq);
    // GiNaC's compare() re-points the less referenced of two equal handles to
    // the other's object. First let the symbol table's handle adopt a popular
    // object, then import through fresh, little-referenced handles: those are
    // the ones re-pointed when they are looked up.
    const GiNaC::ex popular = GiNaC::ex(eq.dofs[0].q);
    const std::vector<GiNaC::ex> holders(50, popular);
    const NodeId expected = importer.import(sin(popular) * eq.params[0].sym);
    for (int round = 0; round < 5; ++round) {
        const GiNaC::ex q = GiNaC::ex(eq.dofs[0].q); // a new object of the same symbol
        CHECK(importer.import(sin(q) * eq.params[0].sym) == expected);
        CHECK(importer.import(-eq.params[1].sym * q) == importer.import(-q * eq.params[1].sym));
    }
}

TEST_CASE("sums and products have one normal form") {
    Graph g;
    const NodeId x = g.symbol({SymbolKind::q, 0});
    const NodeId y = g.symbol({SymbolKind::param, 1});
    const NodeId two_xy = g.mul({{x, 1.0}, {y, 1.0}}, 2.0);
    CHECK(g.add({{x, 1.0}, {y, 1.0}}, 0.0) == g.add({{y, 1.0}, {x, 1.0}}, 0.0));
    CHECK(g.mul({{y, 1.0}, {x, 1.0}}, 2.0) == two_xy);
    // A term's product coefficient moves into the term's weight.
    CHECK(g.add({{two_xy, 1.0}, {x, 1.0}}, 0.0) ==
          g.add({{g.mul({{x, 1.0}, {y, 1.0}}, 1.0), 2.0}, {x, 1.0}}, 0.0));
    // w * x is a product however it was built.
    CHECK(g.add({{two_xy, 1.0}}, 0.0) == two_xy);
    CHECK(g.add({{x, 1.0}, {x, 1.0}}, 0.0) == g.mul({{x, 1.0}}, 2.0));
    CHECK(g.add({{x, 1.0}, {x, -1.0}}, 4.0) == g.number(4.0));
    CHECK(g.add({{g.number(2.0), 1.0}, {g.number(3.0), 2.0}}, 1.0) == g.number(9.0));
    CHECK(g.mul({{x, 1.0}, {x, 1.0}}, 1.0) == g.mul({{x, 2.0}}, 1.0));
    CHECK(g.mul({{x, 2.0}, {x, -2.0}}, 3.0) == g.number(3.0));
    CHECK(g.mul({{x, 1.0}, {g.number(0.0), 1.0}}, 1.0) == g.number(0.0));
    CHECK(g.number(-0.0) == g.number(0.0));
    // The sign of a sum is pulled out: x (y - x) == -x (x - y), (x - y)^2 == (y - x)^2.
    const NodeId x_minus_y = g.add({{x, 1.0}, {y, -1.0}}, 1.0);
    const NodeId y_minus_x = g.add({{y, 1.0}, {x, -1.0}}, -1.0);
    CHECK(g.node(y_minus_x).kind == NodeKind::mul);
    CHECK(g.node(y_minus_x).value == -1.0);
    CHECK(g.mul({{x, 1.0}, {y_minus_x, 1.0}}, 1.0) == g.mul({{x, 1.0}, {x_minus_y, 1.0}}, -1.0));
    CHECK(g.mul({{y_minus_x, 2.0}}, 1.0) == g.mul({{x_minus_y, 2.0}}, 1.0));
    CHECK(g.add({{x_minus_y, 1.0}, {y_minus_x, 1.0}}, 0.0) == g.number(0.0));
    // Powers that are not small integers become calls.
    CHECK(g.mul({{x, 0.5}}, 1.0) == g.call(Function::sqrt, {x}));
    CHECK(g.mul({{x, 5.0}}, 1.0) == g.call(Function::pow, {x, g.number(5.0)}));
    CHECK(g.mul({{x, -0.5}}, 1.0) == g.mul({{g.call(Function::sqrt, {x}), -1.0}}, 1.0));
    CHECK(g.node(g.mul({{x, 4.0}}, 1.0)).kind == NodeKind::mul);
    Graph cubes(2);
    CHECK(cubes.node(cubes.mul({{cubes.symbol({SymbolKind::q, 0}), 3.0}}, 1.0)).kind ==
          NodeKind::call);
}

TEST_CASE("operands are ordered by structure: symbols in declaration order, then compounds") {
    Graph g;
    const NodeId t = g.symbol({SymbolKind::time, 0});
    const NodeId q1 = g.symbol({SymbolKind::q, 1});
    const NodeId q0 = g.symbol({SymbolKind::q, 0});
    const NodeId p0 = g.symbol({SymbolKind::param, 0});
    const NodeId s = g.call(Function::sin, {q0});
    const NodeId sum = g.add({{s, 1.0}, {p0, 1.0}, {q1, 1.0}, {t, 1.0}, {q0, 1.0}}, 0.0);
    std::vector<NodeId> order;
    for (const Operand& op : g.operands(sum)) order.push_back(op.node);
    CHECK(order == std::vector<NodeId>{t, q0, q1, p0, s});
    CHECK(g.compare(q0, q1) < 0);
    CHECK(g.compare(q1, q0) > 0);
    CHECK(g.compare(s, s) == 0);
}

TEST_CASE("symbol dependence is tracked per node") {
    Graph g;
    const NodeId q = g.symbol({SymbolKind::q, 0});
    const NodeId u = g.symbol({SymbolKind::input, 0});
    const NodeId e = g.mul({{g.call(Function::cos, {q}), 1.0}, {u, 1.0}}, 1.0);
    CHECK(g.node(e).depends == ((1u << int(SymbolKind::q)) | (1u << int(SymbolKind::input))));
}

TEST_CASE("importing a DAG whose tree is exponential takes time linear in the DAG") {
    const Equations eq = codegen_test::deep_chain(400); // 3^400 as a tree
    Graph g;
    GinacImporter importer(g, eq);
    const auto start = std::chrono::steady_clock::now();
    importer.import(eq.F[0]);
    importer.import(eq.dF_dq[0][0]);
    importer.import(eq.dMa_dq[0][0]);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 1.0);
    CHECK(g.size() < 20 * 400);
}

TEST_CASE("what generated code cannot express is an internal error, not a crash") {
    const Equations eq = codegen_test::pendulum();
    Graph g;
    GinacImporter importer(g, eq);
    const GiNaC::ex q = eq.dofs[0].q;
    CHECK_THROWS_AS(importer.import(q + GiNaC::symbol("stranger")), yamsc::diag::InternalError);
    CHECK_THROWS_AS(importer.import(q * GiNaC::I), yamsc::diag::InternalError);
    CHECK_THROWS_AS(importer.import(GiNaC::tgamma(q)), yamsc::diag::InternalError);
    CHECK_THROWS_AS(importer.import(GiNaC::lst{q}), yamsc::diag::InternalError);
    // The importer is still usable afterwards.
    CHECK(g.node(importer.import(sin(q))).kind == NodeKind::call);
}
