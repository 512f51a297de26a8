// `approx SYMS order N`: truncated Taylor expansions on expression DAGs, the
// trigonometric identities they must reproduce, and the double pendulum to
// first order in its angles against its hand linearization.
#include "equations_fixture.hpp"
#include "symbolic/approx.hpp"
#include "symbolic/dag.hpp"
#include "symbolic/derive.hpp"
#include "symbolic/tape.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <fstream>

using namespace GiNaC;
using yamsc::symbolic::NotExpandable;
using yamsc::symbolic::TaylorExpansion;

namespace {

const symbol test_x("x"), test_y("y"), test_a("a");

/// Equal as functions of x, y, a: at random points to 1e-13 (the expansion's
/// numbers are doubles, as in generated code).
bool same(const ex& a, const ex& b) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> value(-0.9, 0.9);
    for (int k = 0; k < 5; ++k) {
        yamsc::symbolic::Evaluator::Values values;
        for (const ex& s : {ex(test_x), ex(test_y), ex(test_a)}) values[s] = value(rng);
        yamsc::symbolic::Evaluator ea(values), eb(values);
        const double va = ea(a), vb = eb(b);
        if (std::fabs(va - vb) > 1e-13 * std::max(1.0, std::fabs(vb))) {
            MESSAGE(a << " != " << b << " (" << va << " vs " << vb << ")");
            return false;
        }
    }
    return true;
}

ex expand_in(const ex& e, std::vector<symbol> symbols, int order) {
    TaylorExpansion t(std::move(symbols), order);
    return t(e);
}

} // namespace

TEST_CASE("approx: trigonometric functions of a parameter") {
    const symbol &x = test_x, &y = test_y, &a = test_a;
    // sin x = x - x^3/6 ..., cos x = 1 - x^2/2 + ...
    CHECK(same(expand_in(sin(x), {x}, 2), x));
    CHECK(same(expand_in(cos(x), {x}, 2), 1 - x * x / 2));
    CHECK(same(expand_in(cos(x), {x}, 1), 1));
    CHECK(same(expand_in(sin(x), {x}, 3), x - pow(x, 3) / 6));
    CHECK(same(expand_in(tan(x), {x}, 3), x + pow(x, 3) / 3));
    // About a point that is not zero in the other symbols: sin(a + x).
    CHECK(same(expand_in(sin(a + x), {x}, 2), sin(a) + cos(a) * x - sin(a) * x * x / 2));
    CHECK(same(expand_in(cos(a + 2 * x), {x}, 1), cos(a) - 2 * sin(a) * x));
    // Total order per group: x y is order 2, x^2 y^2 order 4.
    CHECK(same(expand_in(cos(x) * cos(y), {x, y}, 2), 1 - x * x / 2 - y * y / 2));
    CHECK(same(expand_in(sin(x) * sin(y), {x, y}, 2), x * y));
    CHECK(same(expand_in(sin(x) * sin(y), {x, y}, 1), 0));
    // Symbols outside the group stay exact.
    CHECK(same(expand_in(sin(x) * sin(y), {x}, 1), x * sin(y)));
    // Powers: 1/(1 + x), sqrt(1 + x), (a + x)^-2.
    CHECK(same(expand_in(1 / (1 + x), {x}, 2), 1 - x + x * x));
    CHECK(same(expand_in(sqrt(1 + x), {x}, 2), 1 + x / 2 - x * x / 8));
    CHECK(same(expand_in(pow(a + x, -2), {x}, 1), pow(a, -2) - 2 * x * pow(a, -3)));
    CHECK(same(expand_in(exp(x) * (1 + y), {x, y}, 2), 1 + x + y + x * x / 2 + x * y));
    CHECK(same(expand_in(atan(x) + log(1 + x), {x}, 2), 2 * x - x * x / 2));
}

TEST_CASE("approx: what has no expansion is reported") {
    symbol x("x");
    CHECK_THROWS_AS(expand_in(1 / x, {x}, 1), NotExpandable);
    try {
        expand_in(pow(sin(x), -1), {x}, 1);
    } catch (const NotExpandable& e) {
        CHECK_FALSE(e.not_supported); // a pole, not a missing feature
    }
    try {
        expand_in(abs(x), {x}, 1);
        FAIL("abs(x) expanded");
    } catch (const NotExpandable& e) {
        CHECK(e.not_supported);
    }
}

/// The value of an expression whose symbols are all `variables`, walked on a Tape:
/// the Evaluator of dag.hpp goes through GiNaC's op(), which rebuilds (and
/// evaluates) every product factor with an exponent, exponential on deep DAGs.
double tape_value(const ex& e, const std::vector<symbol>& variables,
                  const std::vector<double>& values) {
    using namespace yamsc::symbolic;
    Tape t(variables);
    const TapeId root = t.import(e);
    std::vector<double> v(t.size());
    for (TapeId id = 0; id <= root; ++id) { // operands come before their users
        const TapeTerm* ops = t.operands(id);
        const std::uint32_t n = t.operand_count(id);
        switch (t.kind(id)) {
        case TapeKind::number:
            v[id] = t.value(id);
            break;
        case TapeKind::symbol:
            v[id] = values.at(static_cast<std::size_t>(t.variable_of(id)));
            break;
        case TapeKind::add:
            v[id] = t.value(id);
            for (std::uint32_t i = 0; i < n; ++i) v[id] += ops[i].weight * v[ops[i].node];
            break;
        case TapeKind::mul:
            v[id] = t.value(id);
            for (std::uint32_t i = 0; i < n; ++i) v[id] *= std::pow(v[ops[i].node], ops[i].weight);
            break;
        case TapeKind::power:
            v[id] = std::pow(v[ops[0].node], v[ops[1].node]);
            break;
        case TapeKind::call:
            REQUIRE((t.function(id) == TapeFunction::sin || t.function(id) == TapeFunction::cos));
            v[id] = t.function(id) == TapeFunction::sin ? std::sin(v[ops[0].node])
                                                        : std::cos(v[ops[0].node]);
            break;
        }
    }
    return v[root];
}

TEST_CASE("approx: shared DAGs are expanded once per node") {
    // e_{k+1} = sin(e_k + x) e_k + cos(e_k): a tree of 2^24 nodes, a DAG of ~120.
    // Built without operator* (GiNaC's commutativity check walks the whole tree).
    // Deeper chains are not built here: GiNaC's own `+` sometimes compares equal
    // subtrees recursively (it depends on hash order), which took minutes at 60 levels.
    symbol x("x"), c("c");
    ex e = c;
    for (int k = 0; k < 24; ++k) e = ex(mul(sin(e + x), e)) + cos(e);
    const auto start = std::chrono::steady_clock::now();
    TaylorExpansion t({x}, 2);
    ex approx = t(e);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    MESSAGE("24 nested levels to order 2 in " << seconds << " s");
    CHECK(seconds < 5.0);
    // Against the exact value at small x: the error is O(x^3). At c = 0.3 the
    // iteration converges to pi/2, so use a short chain for a sensitive check.
    ex short_chain = c;
    for (int k = 0; k < 4; ++k)
        short_chain = ex(mul(sin(short_chain + x), short_chain)) + cos(short_chain);
    TaylorExpansion t4({x}, 2);
    const ex approx4 = t4(short_chain);
    for (double xv : {1e-2, 1e-3}) {
        const double err = std::fabs(tape_value(approx4, {x, c}, {xv, 0.3}) -
                                     tape_value(short_chain, {x, c}, {xv, 0.3}));
        MESSAGE("x = " << xv << ": |approx - exact| = " << err);
        CHECK(err < 100 * xv * xv * xv);
        CHECK(err > 0.01 * xv * xv * xv); // a third-order error, not zero: order 2 only
    }
    CHECK(tape_value(approx, {x, c}, {1e-3, 0.3}) ==
          doctest::Approx(tape_value(e, {x, c}, {1e-3, 0.3})).epsilon(1e-6));
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
    const auto& eq = *fe.equations;
    auto exact = yamsc::test::derive_file("models/double_pendulum.mbd");
    yamsc::symbolic::derive_jacobians(exact); // GiNaC's: a reference independent of the IR

    const double m1 = 2.0, m2 = 1.0, L1 = 1.0, L2 = 0.8, g = 9.81, k = 5.0, c = 0.1;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> angle(-1, 1), rate(-2, 2), input(-3, 3);
    for (int n = 0; n < 10; ++n) {
        const double th1 = angle(rng), th2 = angle(rng), w1 = rate(rng), w2 = rate(rng);
        const double tau = input(rng), f = input(rng);
        auto v = yamsc::test::evaluate(eq, {th1, th2}, {w1, w2}, {tau, f});
        // M: the mass matrix at th = 0, whatever the angles.
        CHECK(v.M[0][0] == doctest::Approx(m1 * L1 * L1 + m2 * (L1 + L2) * (L1 + L2)));
        CHECK(v.M[0][1] == doctest::Approx(m2 * L2 * (L1 + L2)));
        CHECK(v.M[1][1] == doctest::Approx(m2 * L2 * L2));
        // F at rest: the linear stiffness of gravity and spring, the inputs at th = 0.
        auto rest = yamsc::test::evaluate(eq, {th1, th2}, {0, 0}, {tau, f});
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
            const double taylor =
                at_zero.F[r] + ev(exact.dF_dq[r][0]) * th1 + ev(exact.dF_dq[r][1]) * th2;
            CHECK(v.F[r] == doctest::Approx(taylor).epsilon(1e-12));
        }
        (void)c;
    }
}
