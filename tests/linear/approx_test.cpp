// `approx SYMS order N` on the IR (passes/taylor.hpp): truncated Taylor
// expansions on expression DAGs, the trigonometric identities they must
// reproduce, and the double pendulum to first order in its angles against its
// hand linearization.
#include "equations_fixture.hpp"
#include "ir/evaluate.hpp"
#include "passes/taylor.hpp"
#include "symbolic/dag.hpp"

#include <doctest/doctest.h>

#include <fstream>

using yamsc::ir::Function;
using yamsc::ir::Graph;
using yamsc::ir::NodeId;
using yamsc::ir::SymbolKind;
using yamsc::ir::SymbolRef;
using yamsc::passes::NotExpandable;
using yamsc::passes::TaylorExpansion;

namespace {

/// Expressions in a graph whose variables are three parameters x, y, a, written
/// with operators.
struct E {
    Graph* g;
    NodeId id;
};
E operator+(E a, E b) {
    return {a.g, a.g->add({{a.id, 1.0}, {b.id, 1.0}}, 0.0)};
}
E operator-(E a, E b) {
    return {a.g, a.g->add({{a.id, 1.0}, {b.id, -1.0}}, 0.0)};
}
E operator*(E a, E b) {
    return {a.g, a.g->mul({{a.id, 1.0}, {b.id, 1.0}}, 1.0)};
}
E operator*(double c, E b) {
    return {b.g, b.g->mul({{b.id, 1.0}}, c)};
}
E operator+(double c, E b) {
    return {b.g, b.g->add({{b.id, 1.0}}, c)};
}
E operator-(double c, E b) {
    return {b.g, b.g->add({{b.id, -1.0}}, c)};
}
E operator/(E a, E b) {
    return {a.g, a.g->mul({{a.id, 1.0}, {b.id, -1.0}}, 1.0)};
}
E operator/(E a, double c) {
    return (1.0 / c) * a;
}
E operator/(double c, E b) {
    return {b.g, b.g->mul({{b.id, -1.0}}, c)};
}
E pow(E a, double e) {
    return {a.g, a.g->power(a.id, a.g->number(e))};
}
E call(Function f, E a) {
    return {a.g, a.g->call(f, {a.id})};
}
E sin(E a) {
    return call(Function::sin, a);
}
E cos(E a) {
    return call(Function::cos, a);
}

struct Fixture {
    Graph g{4, yamsc::ir::Variables{0, 0, 3}};
    E x{&g, g.symbol({SymbolKind::param, 0})};
    E y{&g, g.symbol({SymbolKind::param, 1})};
    E a{&g, g.symbol({SymbolKind::param, 2})};
    E number(double v) { return {&g, g.number(v)}; }

    E expand_in(E e, const std::vector<E>& group, int order) {
        std::vector<SymbolRef> refs;
        for (const E& s : group) refs.push_back(g.node(s.id).symbol);
        TaylorExpansion t(g, refs, order);
        return {&g, t(e.id)};
    }

    double value(E e, const std::vector<double>& xya) {
        return yamsc::ir::evaluate(
            g, {e.id}, [&](SymbolRef s) { return xya.at(static_cast<std::size_t>(s.index)); })[0];
    }

    /// Equal as functions of x, y, a: at random points to 1e-13 (the expansion's
    /// numbers are doubles, as in generated code).
    bool same(E p, E q) {
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> v(-0.9, 0.9);
        for (int k = 0; k < 5; ++k) {
            const std::vector<double> at{v(rng), v(rng), v(rng)};
            const double vp = value(p, at), vq = value(q, at);
            if (std::fabs(vp - vq) > 1e-13 * std::max(1.0, std::fabs(vq))) {
                MESSAGE(vp << " vs " << vq);
                return false;
            }
        }
        return true;
    }
};

} // namespace

TEST_CASE_FIXTURE(Fixture, "approx: trigonometric functions of a parameter") {
    // sin x = x - x^3/6 ..., cos x = 1 - x^2/2 + ...
    CHECK(same(expand_in(sin(x), {x}, 2), x));
    CHECK(same(expand_in(cos(x), {x}, 2), 1 - x * x / 2));
    CHECK(same(expand_in(cos(x), {x}, 1), number(1)));
    CHECK(same(expand_in(sin(x), {x}, 3), x - pow(x, 3) / 6));
    CHECK(same(expand_in(call(Function::tan, x), {x}, 3), x + pow(x, 3) / 3));
    // About a point that is not zero in the other symbols: sin(a + x).
    CHECK(same(expand_in(sin(a + x), {x}, 2), sin(a) + cos(a) * x - sin(a) * x * x / 2));
    CHECK(same(expand_in(cos(a + 2 * x), {x}, 1), cos(a) - 2 * sin(a) * x));
    // Total order per group: x y is order 2, x^2 y^2 order 4.
    CHECK(same(expand_in(cos(x) * cos(y), {x, y}, 2), 1 - x * x / 2 - y * y / 2));
    CHECK(same(expand_in(sin(x) * sin(y), {x, y}, 2), x * y));
    CHECK(same(expand_in(sin(x) * sin(y), {x, y}, 1), number(0)));
    // Symbols outside the group stay exact.
    CHECK(same(expand_in(sin(x) * sin(y), {x}, 1), x * sin(y)));
    // Powers: 1/(1 + x), sqrt(1 + x) (a sqrt call in the graph), (a + x)^-2,
    // (1 + x)^5 (a pow call: beyond the powers written as products).
    CHECK(same(expand_in(1 / (1 + x), {x}, 2), 1 - x + x * x));
    CHECK(same(expand_in(pow(1 + x, 0.5), {x}, 2), 1 + x / 2 - x * x / 8));
    CHECK(same(expand_in(pow(a + x, -2), {x}, 1), pow(a, -2) - 2 * x * pow(a, -3)));
    CHECK(same(expand_in(pow(1 + x, 5), {x}, 2), 1 + 5 * x + 10 * x * x));
    CHECK(same(expand_in(call(Function::exp, x) * (1 + y), {x, y}, 2),
               1 + x + y + x * x / 2 + x * y));
    CHECK(same(expand_in(call(Function::atan, x) + call(Function::log, 1 + x), {x}, 2),
               2 * x - x * x / 2));
    // Through the derivatives at the expansion point: asin(a + x) to order 2.
    CHECK(same(expand_in(call(Function::asin, 0.5 * a + x), {x}, 2),
               call(Function::asin, 0.5 * a) + x / pow(1 - 0.25 * a * a, 0.5) +
                   0.25 * a * x * x / pow(1 - 0.25 * a * a, 1.5)));
}

TEST_CASE_FIXTURE(Fixture, "approx: what has no expansion is reported") {
    CHECK_THROWS_AS(expand_in(1 / x, {x}, 1), NotExpandable);
    try {
        expand_in(1 / sin(x), {x}, 1);
        FAIL("1/sin(x) expanded");
    } catch (const NotExpandable& e) {
        CHECK_FALSE(e.not_supported); // a pole, not a missing feature
    }
    try {
        expand_in(call(Function::abs, x), {x}, 1);
        FAIL("abs(x) expanded");
    } catch (const NotExpandable& e) {
        CHECK(e.not_supported);
    }
}

TEST_CASE_FIXTURE(Fixture, "approx: shared DAGs are expanded once per node") {
    // e_{k+1} = sin(e_k + x) e_k + cos(e_k): a tree of 2^40 nodes, a DAG of ~200.
    // Expanded as a tree it could not finish; memoised per node, each level adds
    // a bounded number of coefficient nodes.
    E e = y;
    for (int k = 0; k < 40; ++k) e = sin(e + x) * e + cos(e);
    const std::size_t before = g.size();
    const E approx = expand_in(e, {x}, 2);
    MESSAGE("40 nested levels to order 2: " << g.size() - before << " new nodes");
    CHECK(g.size() - before < 60 * 40); // 1401 when written
    // Against the exact value at small x: the error is O(x^3). At y = 0.3 the
    // iteration converges to pi/2, so use a short chain for a sensitive check.
    E short_chain = y;
    for (int k = 0; k < 4; ++k) short_chain = sin(short_chain + x) * short_chain + cos(short_chain);
    const E approx4 = expand_in(short_chain, {x}, 2);
    for (double xv : {1e-2, 1e-3}) {
        const double err =
            std::fabs(value(approx4, {xv, 0.3, 0}) - value(short_chain, {xv, 0.3, 0}));
        MESSAGE("x = " << xv << ": |approx - exact| = " << err);
        CHECK(err < 100 * xv * xv * xv);
        CHECK(err > 0.01 * xv * xv * xv); // a third-order error, not zero: order 2 only
    }
    CHECK(value(approx, {1e-3, 0.3, 0}) == doctest::Approx(value(e, {1e-3, 0.3, 0})).epsilon(1e-6));
}

TEST_CASE("approx: the double pendulum to first order in its angles is its hand linearization") {
    // The tutorial's double pendulum with `approx th1, th2 order 1`.
    const std::string path = std::string(YAMSC_TEST_BINARY_DIR) + "/double_pendulum_approx.mbd";
    {
        std::ifstream in(yamsc::test::source_path("models/double_pendulum.mbd"));
        std::string text((std::istreambuf_iterator<char>(in)), {});
        std::ofstream out(path);
        out << text << "\napprox th1, th2 order 1\n";
    }
    yamsc::diag::Diagnostics diags;
    auto fe = yamsc::driver::run_front_end(path, yamsc::driver::Until::jacobians, diags);
    INFO(diags.render());
    REQUIRE_FALSE(diags.has_errors());
    REQUIRE(fe.system);
    const yamsc::ir::System& sys = *fe.system;
    REQUIRE(sys.exact_F.size() == 2); // approximated
    // M and F as compiled (approximated on the IR), parameters at their defaults.
    auto compiled = [&](const std::vector<double>& q, const std::vector<double>& qd,
                        const std::vector<double>& u) {
        std::vector<NodeId> roots{sys.M[0][0], sys.M[0][1], sys.M[1][1], sys.F[0], sys.F[1]};
        const auto v = yamsc::ir::evaluate(sys.graph, roots, [&](SymbolRef s) {
            const auto i = static_cast<std::size_t>(s.index);
            switch (s.kind) {
            case SymbolKind::q:
                return q.at(i);
            case SymbolKind::qd:
                return qd.at(i);
            case SymbolKind::input:
                return u.at(i);
            case SymbolKind::param:
                return *sys.params.at(i).value;
            default:
                return 0.0;
            }
        });
        yamsc::test::Evaluated out;
        out.M = {{v[0], v[1]}, {v[1], v[2]}};
        out.F = {v[3], v[4]};
        return out;
    };
    // The reference: the exact GiNaC equations, and dF/dq by GiNaC's
    // differentiation (dag.hpp): independent of the IR and its passes.
    const auto exact = yamsc::test::derive_file("models/double_pendulum.mbd");
    std::vector<std::vector<GiNaC::ex>> dF_dq(2, std::vector<GiNaC::ex>(2));
    for (std::size_t k = 0; k < 2; ++k) {
        yamsc::symbolic::Differentiator d(exact.dofs[k].q);
        for (std::size_t r = 0; r < 2; ++r) dF_dq[r][k] = d(exact.F[r]);
    }

    const double m1 = 2.0, m2 = 1.0, L1 = 1.0, L2 = 0.8, g = 9.81, k = 5.0, c = 0.1;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> angle(-1, 1), rate(-2, 2), input(-3, 3);
    for (int n = 0; n < 10; ++n) {
        const double th1 = angle(rng), th2 = angle(rng), w1 = rate(rng), w2 = rate(rng);
        const double tau = input(rng), f = input(rng);
        auto v = compiled({th1, th2}, {w1, w2}, {tau, f});
        // M: the mass matrix at th = 0, whatever the angles.
        CHECK(v.M[0][0] == doctest::Approx(m1 * L1 * L1 + m2 * (L1 + L2) * (L1 + L2)));
        CHECK(v.M[0][1] == doctest::Approx(m2 * L2 * (L1 + L2)));
        CHECK(v.M[1][1] == doctest::Approx(m2 * L2 * L2));
        // F at rest: the linear stiffness of gravity and spring, the inputs at th = 0.
        auto rest = compiled({th1, th2}, {0, 0}, {tau, f});
        CHECK(rest.F[0] == doctest::Approx(-(m1 + m2) * g * L1 * th1 - m2 * g * L2 * (th1 + th2) +
                                           tau - f * (L1 + L2)));
        CHECK(rest.F[1] ==
              doctest::Approx(-m2 * g * L2 * (th1 + th2) - k * th2 - f * L2).epsilon(1e-12));
        // With rates: F(0, w) + dF/dq(0, w) th of the exact model (the velocity terms
        // stay exact in the rates, first order in the angles).
        auto at_zero = yamsc::test::evaluate(exact, {0, 0}, {w1, w2}, {tau, f});
        yamsc::symbolic::Evaluator::Values values;
        values[exact.t] = 0;
        for (std::size_t i = 0; i < 2; ++i) {
            values[exact.dofs[i].q] = 0;
            values[exact.dofs[i].qd] = i == 0 ? w1 : w2;
        }
        values[exact.inputs[0].sym] = tau;
        values[exact.inputs[1].sym] = f;
        for (const auto& p : exact.params) values[p.sym] = *p.value;
        yamsc::symbolic::Evaluator ev(values);
        for (std::size_t r = 0; r < 2; ++r) {
            const double taylor = at_zero.F[r] + ev(dF_dq[r][0]) * th1 + ev(dF_dq[r][1]) * th2;
            CHECK(v.F[r] == doctest::Approx(taylor).epsilon(1e-12));
        }
        (void)c;
    }
}
