// The expression printer: exact text for each rule (powers, divisions, signs,
// parentheses, numbers, functions) and its operation counts.
#include "codegen/body.hpp"
#include "codegen/module.hpp"
#include "codegen/syntax.hpp"
#include "fixtures.hpp"

#include <algorithm>
#include <doctest/doctest.h>

using namespace yamsc::codegen;
using codegen_test::build_module;
using codegen_test::Equations;
using GiNaC::ex;

namespace {

/// One DOF q, parameters a, b; F = [f], M = [1], zero Jacobians.
struct OneForce {
    Equations eq;
    ex q, qd, a, b;
    OneForce() {
        eq.model_name = "one";
        eq.t = GiNaC::symbol("t");
        eq.dofs.push_back({"q", "", GiNaC::symbol("q"), GiNaC::symbol("qd"), GiNaC::symbol("qdd")});
        eq.params.push_back({"a", "", 1.0, GiNaC::symbol("a")});
        eq.params.push_back({"b", "", 2.0, GiNaC::symbol("b")});
        eq.a = {GiNaC::symbol("a0")};
        eq.M = {{1}};
        eq.dF_dq = {{0}};
        eq.dF_dqd = {{0}};
        eq.dF_du = {{}};
        eq.dMa_dq = {{0}};
        q = eq.dofs[0].q;
        qd = eq.dofs[0].qd;
        a = eq.params[0].sym;
        b = eq.params[1].sym;
    }
    BodyText forcing(const ex& f, const Syntax& syntax = cpp_syntax()) {
        eq.F = {f};
        const Module m = build_module(eq);
        return body_text(m.routine("forcing"), m, syntax, {"t", "q", "qd", "u", "p", "F"});
    }
    /// The statements after the (void) casts.
    std::string text(const ex& f, const Syntax& syntax = cpp_syntax()) {
        std::string body = forcing(f, syntax).text;
        std::string out;
        std::size_t pos = 0;
        while (pos < body.size()) {
            // The last line may lack its '\n': end there, not back at the start.
            const std::size_t end = std::min(body.find('\n', pos), body.size());
            const std::string line = body.substr(pos, end - pos);
            if (line.find("(void)") == std::string::npos) out += line.substr(4) + "\n";
            pos = end + 1;
        }
        return out;
    }
};

} // namespace

TEST_CASE("numbers print exactly and always read as doubles") {
    CHECK(format_number(1.0) == "1.0");
    CHECK(format_number(-2.5) == "-2.5");
    CHECK(format_number(0.1) == "0.1");
    CHECK(format_number(9.807) == "9.807");
    CHECK(format_number(1e-5) == "1e-05");
    CHECK(format_number(1e20) == "1e+20");
    CHECK(format_number(123456789012.0) == "123456789012.0");
    CHECK(format_number(1.0 / 3.0) == "0.3333333333333333");
    CHECK(std::stod(format_number(0.1 + 0.2)) == 0.1 + 0.2);
}

TEST_CASE("powers: small integers multiply, 1/2 is sqrt, the rest call pow") {
    OneForce o;
    CHECK(o.text(pow(o.q, 2)) == "F[0] = q[0]*q[0];\n");
    CHECK(o.text(pow(o.q, 4)) == "F[0] = q[0]*q[0]*q[0]*q[0];\n");
    CHECK(o.text(pow(o.q, -1)) == "F[0] = 1.0/q[0];\n");
    CHECK(o.text(pow(o.q, -2) * o.a) == "F[0] = p.a/(q[0]*q[0]);\n");
    CHECK(o.text(sqrt(o.q)) == "const double t0 = std::sqrt(q[0]);\nF[0] = t0;\n");
    CHECK(o.text(pow(o.q, GiNaC::numeric(-1, 2))) ==
          "const double t0 = std::sqrt(q[0]);\nF[0] = 1.0/t0;\n");
    CHECK(o.text(pow(o.q, 5)) == "const double t0 = std::pow(q[0], 5.0);\nF[0] = t0;\n");
    CHECK(o.text(pow(o.q, o.a)) == "const double t0 = std::pow(q[0], p.a);\nF[0] = t0;\n");
    // The base of a repeated product is a name, never a repeated expression.
    CHECK(o.text(pow(o.a + o.b, 2)) == "const double t0 = p.a + p.b;\nF[0] = t0*t0;\n");
    CHECK(o.text(pow(sin(o.q), 2)) == "const double t0 = std::sin(q[0]);\nF[0] = t0*t0;\n");
}

TEST_CASE("signs, quotients and parentheses") {
    OneForce o;
    CHECK(o.text(o.a - o.b) == "F[0] = p.a - p.b;\n");
    CHECK(o.text(-o.a - o.b) == "F[0] = -p.a - p.b;\n");
    CHECK(o.text(o.a - 2 * o.b) == "F[0] = p.a - 2.0*p.b;\n");
    CHECK(o.text(-o.a * o.q) == "F[0] = -q[0]*p.a;\n");
    CHECK(o.text(o.q + 1) == "F[0] = q[0] + 1.0;\n");
    CHECK(o.text(o.q - 1) == "F[0] = q[0] - 1.0;\n");
    CHECK(o.text(ex(-2)) == "F[0] = -2.0;\n");
    CHECK(o.text((o.a + o.b) * o.q) == "F[0] = q[0]*(p.a + p.b);\n");
    CHECK(o.text(2 * o.a * o.q / o.b) == "F[0] = 2.0*q[0]*p.a/p.b;\n");
    CHECK(o.text(o.q / (o.a * o.b)) == "F[0] = q[0]/(p.a*p.b);\n");
    CHECK(o.text(1 / (1 + o.q)) == "F[0] = 1.0/(q[0] + 1.0);\n");
    CHECK(o.text(o.q * o.a - 3 * o.qd / o.b + GiNaC::numeric(3, 2)) ==
          "F[0] = q[0]*p.a - 3.0*qd[0]/p.b + 1.5;\n");
    CHECK(o.text(o.eq.t * o.a) == "F[0] = t*p.a;\n");
}

TEST_CASE("constants and functions") {
    OneForce o;
    CHECK(o.text(GiNaC::Pi * o.q) == "F[0] = 3.141592653589793*q[0];\n");
    CHECK(o.text(o.q / 3) == "F[0] = 0.3333333333333333*q[0];\n");
    CHECK(o.text(exp(-pow(o.q, 2))) == "const double t0 = std::exp(-q[0]*q[0]);\nF[0] = t0;\n");
    CHECK(o.text(atan2(o.q, o.a)) == "const double t0 = std::atan2(q[0], p.a);\nF[0] = t0;\n");
    CHECK(o.text(abs(o.q) * o.a) == "const double t0 = std::abs(q[0]);\nF[0] = p.a*t0;\n");
    CHECK(o.text(abs(o.q) * o.a, c_syntax("one")) ==
          "const double t0 = fabs(q[0]);\nF[0] = p->a*t0;\n");
}

TEST_CASE("operation counts are those of the printed text") {
    OneForce o;
    // q[0]*p.a - 3.0*qd[0]/p.b + 1.5: 2 adds, 2 muls, 1 div.
    const OperationCount c = o.forcing(o.q * o.a - 3 * o.qd / o.b + GiNaC::numeric(3, 2)).count;
    CHECK(c.adds == 2);
    CHECK(c.muls == 2);
    CHECK(c.divs == 1);
    CHECK(c.calls == 0);
    // t0 = std::sin(q[0]); t0*t0*t0 - 1.0/(p.a*p.b)
    const OperationCount d = o.forcing(pow(sin(o.q), 3) - 1 / (o.a * o.b)).count;
    CHECK(d.adds == 1);
    CHECK(d.muls == 3);
    CHECK(d.divs == 1);
    CHECK(d.calls == 1);
}

TEST_CASE("deeply nested single-use expressions are cut into temporaries") {
    OneForce o;
    ex e = o.q;
    for (int k = 0; k < 200; ++k) e = (e + o.a) * (o.b + k);
    const std::string text = o.text(e);
    int depth = 0, deepest = 0;
    for (const char c : text) {
        depth += c == '(' ? 1 : (c == ')' ? -1 : 0);
        deepest = std::max(deepest, depth);
    }
    CHECK(deepest <= 2 * 32 + 2);
    CHECK(text.find("const double t0 = ") != std::string::npos);
}
