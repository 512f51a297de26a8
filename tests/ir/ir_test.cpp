// Stage tests of the intermediate representation and its passes: dependence
// sets, forward-mode derivatives against finite differences, the passes on a
// small System, and the layering rule that code generation does not derive.
#include "ir/evaluate.hpp"
#include "ir/graph.hpp"
#include "ir/system.hpp"
#include "passes/forward.hpp"
#include "passes/passes.hpp"
#include "two_dof_system.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace yamsc::ir;
using yamsc::passes::ForwardDerivative;

namespace {

// q0, q1 (variables 0, 1), q0', q1' (2, 3), one input (4), one parameter (5).
const Variables two_dofs{2, 1, 1};

struct Values {
    std::vector<double> q{0.7, -0.4}, qd{0.3, 1.1}, u{0.25}, p{1.9};
    double symbol(SymbolRef s) const {
        switch (s.kind) {
        case SymbolKind::q:
            return q[static_cast<std::size_t>(s.index)];
        case SymbolKind::qd:
            return qd[static_cast<std::size_t>(s.index)];
        case SymbolKind::input:
            return u[static_cast<std::size_t>(s.index)];
        case SymbolKind::param:
            return p[static_cast<std::size_t>(s.index)];
        default:
            return 0.0;
        }
    }
    double& variable(int v) {
        if (v < 2) return q[static_cast<std::size_t>(v)];
        if (v < 4) return qd[static_cast<std::size_t>(v - 2)];
        if (v < 5) return u[0];
        return p[0];
    }
};

double value(const Graph& g, NodeId id, const Values& x) {
    return evaluate(g, {id}, [&](SymbolRef s) { return x.symbol(s); })[0];
}

/// Central difference of `f` in variable v.
double difference(const Graph& g, NodeId f, Values x, int v) {
    const double h = 1e-6;
    const double x0 = x.variable(v);
    x.variable(v) = x0 + h;
    const double up = value(g, f, x);
    x.variable(v) = x0 - h;
    const double down = value(g, f, x);
    return (up - down) / (2 * h);
}

/// Every elementary function, powers (integer, half, other, symbolic) and a sum
/// whose sign the Graph normalises.
NodeId test_expression(Graph& g) {
    const NodeId q0 = g.symbol({SymbolKind::q, 0}), q1 = g.symbol({SymbolKind::q, 1});
    const NodeId qd0 = g.symbol({SymbolKind::qd, 0}), u = g.symbol({SymbolKind::input, 0});
    const NodeId p = g.symbol({SymbolKind::param, 0});
    const NodeId r = g.add({{g.mul({{q0, 2.0}}, 1.0), 1.0}}, 2.0);         // 2 + q0^2 > 0
    const NodeId small = g.mul({{g.call(Function::sin, {q1}), 1.0}}, 0.5); // |.| < 1
    std::vector<Operand> terms{
        {g.mul({{g.call(Function::sin, {q0}), 1.0}, {q1, 2.0}}, 1.0), 1.0},
        {g.mul({{g.call(Function::cos, {q1}), 1.0}, {qd0, 1.0}, {p, 1.0}}, 1.0), -3.0},
        {g.call(Function::tan, {small}), 1.0},
        {g.call(Function::asin, {small}), 1.0},
        {g.call(Function::acos, {small}), 1.0},
        {g.call(Function::atan, {q0}), 1.0},
        {g.call(Function::atan2, {q1, r}), 1.0},
        {g.call(Function::sinh, {small}), 1.0},
        {g.call(Function::cosh, {small}), 1.0},
        {g.call(Function::tanh, {q0}), 1.0},
        {g.call(Function::asinh, {q1}), 1.0},
        {g.call(Function::acosh, {r}), 1.0},
        {g.call(Function::atanh, {small}), 1.0},
        {g.call(Function::exp, {g.mul({{u, 1.0}, {q0, 1.0}}, 1.0)}), 1.0},
        {g.call(Function::log, {r}), 1.0},
        {g.call(Function::abs, {q1}), 1.0},
        {g.mul({{r, 0.5}}, 1.0), 1.0},                        // sqrt
        {g.mul({{r, -1.5}, {q1, 1.0}}, 1.0), 1.0},            // pow, negative
        {g.mul({{q0, 6.0}}, 1.0), 1.0},                       // beyond repeated products
        {g.power(r, g.add({{q1, 1.0}, {p, 1.0}}, 0.0)), 1.0}, // symbolic exponent
        {g.add({{q1, -1.0}, {q0, 1.0}}, 0.0), 2.0},           // sign normalised
    };
    return g.add(std::move(terms), 1.0);
}

} // namespace

TEST_CASE("each node knows the variables it depends on") {
    Graph g(4, two_dofs);
    const NodeId q1 = g.symbol({SymbolKind::q, 1});
    const NodeId p = g.symbol({SymbolKind::param, 0});
    const NodeId t = g.symbol({SymbolKind::time, 0});
    const NodeId e = g.mul({{g.call(Function::sin, {q1}), 1.0}, {p, 1.0}, {t, 1.0}}, 2.0);
    CHECK(two_dofs.of({SymbolKind::q, 1}) == 1);
    CHECK(two_dofs.of({SymbolKind::param, 0}) == 5);
    CHECK(two_dofs.of({SymbolKind::time, 0}) == -1);
    CHECK(g.depends(e, 1));
    CHECK(g.depends(e, 5));
    for (int v : {0, 2, 3, 4}) CHECK_FALSE(g.depends(e, static_cast<std::size_t>(v)));
    // Structural equality survives the dependence bookkeeping.
    CHECK(e == g.mul({{p, 1.0}, {t, 1.0}, {g.call(Function::sin, {q1}), 1.0}}, 2.0));
}

TEST_CASE("forward-mode derivatives agree with finite differences for every function") {
    Graph g(4, two_dofs);
    const NodeId f = test_expression(g);
    const Values x;
    for (int v = 0; v < two_dofs.count(); ++v) {
        ForwardDerivative d(g, static_cast<std::size_t>(v));
        const double exact = value(g, d(f), x);
        const double numeric = difference(g, f, x, v);
        INFO("variable " << v);
        CHECK(exact == doctest::Approx(numeric).epsilon(1e-6));
    }
}

TEST_CASE("a directional derivative is the seeded sum of the partial ones") {
    Graph g(4, two_dofs);
    const NodeId f = test_expression(g);
    std::vector<NodeId> seeds;
    for (int v = 0; v < two_dofs.count(); ++v) seeds.push_back(g.symbol({SymbolKind::seed, v}));
    ForwardDerivative along(g, seeds);
    const NodeId df = along(f);
    const std::vector<double> direction{0.3, -1.2, 0.5, 2.0, -0.7, 0.9};
    const Values x;
    const double got = evaluate(g, {df}, [&](SymbolRef s) {
        return s.kind == SymbolKind::seed ? direction[static_cast<std::size_t>(s.index)]
                                          : x.symbol(s);
    })[0];
    double expected = 0.0;
    for (int v = 0; v < two_dofs.count(); ++v) {
        ForwardDerivative d(g, static_cast<std::size_t>(v));
        expected += direction[static_cast<std::size_t>(v)] * value(g, d(f), x);
    }
    CHECK(got == doctest::Approx(expected).epsilon(1e-12));
}

TEST_CASE("a derivative visits only what depends on its variable and shares the rest") {
    Graph g(4, two_dofs);
    const NodeId q0 = g.symbol({SymbolKind::q, 0}), q1 = g.symbol({SymbolKind::q, 1});
    NodeId x = q0;
    for (int level = 0; level < 200; ++level) // a chain whose tree is exponential
        x = g.add({{g.mul({{g.call(Function::sin, {x}), 1.0}, {x, 1.0}}, 1.0), 1.0}, {x, 0.5}},
                  0.0);
    const NodeId f = g.mul({{x, 1.0}, {g.call(Function::cos, {q1}), 1.0}}, 1.0);
    const std::size_t before = g.size();
    ForwardDerivative d_q1(g, 1);
    const NodeId df = d_q1(f);
    CHECK(g.size() - before < 10); // -x sin(q1): a few new nodes
    CHECK(value(g, df, Values{}) == doctest::Approx(difference(g, f, Values{}, 1)).epsilon(1e-6));
    ForwardDerivative d_qd0(g, 2);
    CHECK(d_qd0(f) == g.number(0.0));
}

TEST_CASE("the passes fill the rows of a System") {
    System s = ir_test::two_dof_system();
    yamsc::passes::derive_jacobians(s);
    yamsc::passes::output_jacobians(s);
    const Values x;
    auto at = [&](NodeId id, const std::vector<double>& a = {0.0, 0.0}) {
        return evaluate(s.graph, {id}, [&](SymbolRef r) {
            return r.kind == SymbolKind::acceleration ? a[static_cast<std::size_t>(r.index)]
                                                      : x.symbol(r);
        })[0];
    };
    // dF0/dq0 = -k qd1, dF0/dq1' = -k q0, dF1/du = q1^2, dF1/dq1 = 2 u q1.
    CHECK(at(s.dF_dq[0][0]) == doctest::Approx(-1.9 * 1.1));
    CHECK(at(s.dF_dqd[0][1]) == doctest::Approx(-1.9 * 0.7));
    CHECK(at(s.dF_du[1][0]) == doctest::Approx(0.16));
    CHECK(at(s.dF_dq[1][1]) == doctest::Approx(2 * 0.25 * -0.4));
    // M a formed from M: d(M a)/dq0 row 0 = -sin(q0 - q1) a1.
    const std::vector<double> a{0.5, -2.0};
    CHECK(at(s.dMa_dq[0][0], a) == doctest::Approx(-std::sin(1.1) * -2.0));
    CHECK(at(s.dMa_dq[1][1], a) == doctest::Approx(std::sin(1.1) * 0.5));
    // C = [dy/dq, dy/dq'], D = dy/du.
    CHECK(at(s.C[0][0]) == doctest::Approx(0.25));
    CHECK(at(s.C[0][3]) == doctest::Approx(0.0));
    CHECK(at(s.D[0][0]) == doctest::Approx(0.7));
    yamsc::passes::parameter_derivatives(s, {0});
    REQUIRE(s.sensitivities.size() == 1);
    CHECK(at(s.sensitivities[0].M[1][1]) == doctest::Approx(1.0));
    CHECK(at(s.sensitivities[0].dF_dq[0][0]) == doctest::Approx(-1.1));
    yamsc::passes::derive_tangent(s);
    REQUIRE(s.dG.size() == 2);
    CHECK(s.tangent_form);
}

TEST_CASE("code generation does not derive: no codegen file includes a symbolic header") {
    // Code generation lowers the IR and prints it (C++, C and LaTeX); the
    // derivatives come from the passes, and GiNaC stays behind the import.
    const std::filesystem::path dir = std::filesystem::path(YAMSC_SOURCE_DIR) / "compiler/codegen";
    std::vector<std::string> offenders;
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue; // helpers/: C sources, no includes
        const std::string name = entry.path().filename().string();
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        ++files;
        if (text.str().find("#include \"symbolic/") != std::string::npos ||
            text.str().find("#include <ginac") != std::string::npos)
            offenders.push_back(name);
    }
    std::sort(offenders.begin(), offenders.end());
    CHECK(files > 20);
    CHECK(offenders.empty());
}
