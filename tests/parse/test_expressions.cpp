// Expressions: precedence, associativity, deg, primes, calls, vectors, components, numbers,
// and ast::to_string printing them back with minimal parentheses.
#include "parse_test_support.hpp"

#include <doctest/doctest.h>

using namespace yamsc;

namespace {

/// The tree as an s-expression, independent of ast::to_string.
std::string sexpr(const ast::Expr& e) {
    using K = ast::Expr::Kind;
    const auto args = [&] {
        std::string out;
        for (const ast::Expr& a : e.args) out += " " + sexpr(a);
        return out;
    };
    switch (e.kind) {
    case K::number:
        return e.text;
    case K::name:
        return e.text + std::string(static_cast<std::size_t>(e.primes), '\'');
    case K::neg:
        return "(neg" + args() + ")";
    case K::add:
        return "(+" + args() + ")";
    case K::sub:
        return "(-" + args() + ")";
    case K::mul:
        return "(*" + args() + ")";
    case K::div:
        return "(/" + args() + ")";
    case K::pow:
        return "(^" + args() + ")";
    case K::deg:
        return "(deg" + args() + ")";
    case K::call:
        return "(call " + e.text + args() + ")";
    case K::vector:
        return "(vec" + args() + ")";
    case K::component:
        return "(." + e.text + args() + ")";
    case K::section:
        return "(section " + e.text + args() + ")";
    }
    return "?";
}

ast::Expr expr_ok(const std::string& text) {
    diag::Diagnostics diags;
    std::optional<ast::Expr> e = test::parse_expr(text, diags);
    INFO(text);
    INFO(diags.render());
    REQUIRE(e.has_value());
    return std::move(*e);
}

std::string tree(const std::string& text) {
    return sexpr(expr_ok(text));
}

std::string errors(const std::string& text) {
    diag::Diagnostics diags;
    CHECK_FALSE(test::parse_expr(text, diags).has_value());
    return test::brief(diags);
}

} // namespace

TEST_CASE("binary operators: precedence and left associativity") {
    CHECK(tree("a + b * c") == "(+ a (* b c))");
    CHECK(tree("a * b + c") == "(+ (* a b) c)");
    CHECK(tree("a - b - c") == "(- (- a b) c)");
    CHECK(tree("a / b / c") == "(/ (/ a b) c)");
    CHECK(tree("a / b * c") == "(* (/ a b) c)");
    CHECK(tree("a - b + c") == "(+ (- a b) c)");
    CHECK(tree("(a + b) * c") == "(* (+ a b) c)");
    CHECK(tree("a*b+c/d-e") == "(- (+ (* a b) (/ c d)) e)");
}

TEST_CASE("power: right associative, tighter than unary minus") {
    CHECK(tree("a ^ b ^ c") == "(^ a (^ b c))");
    CHECK(tree("-x^2") == "(neg (^ x 2))");
    CHECK(tree("-2^2") == "(neg (^ 2 2))");
    CHECK(tree("(-x)^2") == "(^ (neg x) 2)");
    CHECK(tree("x^-2") == "(^ x (neg 2))");
    CHECK(tree("2^-x^2") == "(^ 2 (neg (^ x 2)))");
    CHECK(tree("a*b^c") == "(* a (^ b c))");
    CHECK(tree("(a^b)^c") == "(^ (^ a b) c)");
}

TEST_CASE("unary minus and plus") {
    CHECK(tree("-a") == "(neg a)");
    CHECK(tree("--a") == "(neg (neg a))");
    CHECK(tree("a - -b") == "(- a (neg b))");
    CHECK(tree("a * -b") == "(* a (neg b))");
    CHECK(tree("-a * b") == "(* (neg a) b)");
    CHECK(tree("+a") == "a");
    CHECK(tree("a + +b") == "(+ a b)");
}

TEST_CASE("deg: postfix on a power, with or without a space") {
    CHECK(tree("5 deg") == "(deg 5)");
    CHECK(tree("5deg") == "(deg 5)");
    CHECK(tree("(a+b) deg") == "(deg (+ a b))");
    CHECK(tree("-5 deg") == "(neg (deg 5))");
    CHECK(tree("x^2 deg") == "(deg (^ x 2))");
    CHECK(tree("2*5 deg") == "(* 2 (deg 5))");
    CHECK(tree("a + 90deg / 2") == "(+ a (/ (deg 90) 2))");
    CHECK(tree("theta deg") == "(deg theta)");
}

TEST_CASE("names: primes, t, and keywords-like names") {
    const ast::Expr q1 = expr_ok("q'");
    CHECK(q1.kind == ast::Expr::Kind::name);
    CHECK(q1.text == "q");
    CHECK(q1.primes == 1);
    CHECK(expr_ok("q''").primes == 2);
    CHECK(expr_ok("t").kind == ast::Expr::Kind::name);
    CHECK(tree("psi' * t") == "(* psi' t)");
    CHECK(tree("x + y + z") == "(+ (+ x y) z)");
}

TEST_CASE("calls, vectors, parentheses and components") {
    CHECK(tree("sin(x)") == "(call sin x)");
    CHECK(tree("atan2(y, x)") == "(call atan2 y x)");
    CHECK(tree("sqrt (a)") == "(call sqrt a)");
    CHECK(tree("f()") == "(call f)");
    CHECK(tree("(a)") == "a");
    CHECK(tree("((a))") == "a");
    CHECK(tree("(a, b)") == "(vec a b)");
    CHECK(tree("(0, 0, -g)") == "(vec 0 0 (neg g))");
    CHECK(tree("(a, (b, c))") == "(vec a (vec b c))");
    CHECK(tree("position(nacelle).x") == "(.x (call position nacelle))");
    CHECK(tree("(a, b, c).z * 2") == "(* (.z (vec a b c)) 2)");
    CHECK(tree("v.x.y") == "(.y (.x v))");
    CHECK(tree("-v.x^2") == "(neg (^ (.x v) 2))");
    CHECK(tree("(1,\n  2, # second\n  3)") == "(vec 1 2 3)");
    CHECK(tree("f(a,\n b)") == "(call f a b)");
    // Sections of a flexible body (the checker allows them in reactions only).
    CHECK(tree("reaction_moment(tower.node(10)).y") ==
          "(.y (call reaction_moment (section node tower 10)))");
    CHECK(tree("reaction_force(blade.tip).x") == "(.x (call reaction_force (section tip blade)))");
    CHECK(tree("tower.node (2 + 1).z") == "(.z (section node tower (+ 2 1)))");
    CHECK(ast::to_string(expr_ok("reaction_moment(tower.node(10)).y")) ==
          "reaction_moment(tower.node(10)).y");
}

TEST_CASE("numbers keep their text exactly") {
    for (const char* n : {"12", "1.5", "2.5e-3", "1E+4", ".5", "5.", "1e99999", "007"}) {
        const ast::Expr e = expr_ok(n);
        CHECK(e.kind == ast::Expr::Kind::number);
        CHECK(e.text == n);
    }
}

TEST_CASE("expression positions are 1-based line and column") {
    const ast::Expr e = expr_ok("a + sin(b)*c");
    CHECK(e.loc.line == 1);
    CHECK(e.loc.col == 3); // the operator
    CHECK(e.args[0].loc.col == 1);
    const ast::Expr& mul = e.args[1];
    CHECK(mul.loc.col == 11);
    CHECK(mul.args[0].kind == ast::Expr::Kind::call);
    CHECK(mul.args[0].loc.col == 5);
    CHECK(mul.args[0].args[0].loc.col == 9);
    CHECK(expr_ok("(1, 2)").loc.col == 1);
}

TEST_CASE("expression syntax errors") {
    CHECK(errors("") == "1:1: expected an expression, found end of file [syntax]\n");
    CHECK(errors("a +") == "1:4: expected an expression after the operator, found end of file "
                           "[syntax]\n");
    CHECK(errors("a + * b") ==
          "1:5: expected an expression after the operator, found '*' [syntax]\n");
    CHECK(errors("(a, b") ==
          "1:6: expected ',' or ')' to close the '(' at 1:1, found end of file [syntax]\n");
    CHECK(errors("f(a b)") ==
          "1:5: expected ',' or ')' to close the call started at 1:2, found 'b' [syntax]\n");
    CHECK(errors("q'''") == "1:4: too many primes: at most two (q'') are allowed [syntax]\n");
    CHECK(errors("2x") == "1:2: unexpected 'x' directly after a number [syntax]\n");
    CHECK(errors("1e") == "1:2: unexpected 'e' directly after a number [syntax]\n");
    CHECK(errors("a.w") == "1:3: expected x, y or z after '.', found 'w' [syntax]\n");
    CHECK(errors("a b") == "1:3: expected the end of the expression, found 'b' [syntax]\n");
    CHECK(errors("5 deg deg") == "1:7: expected the end of the expression, found 'deg' [syntax]\n");
    CHECK(errors("a ** b") ==
          "1:4: expected an expression after the operator, found '*' [syntax]\n");
    CHECK(errors("0.7 z^2") == "1:5: expected the end of the expression, found 'z' [syntax]\n");
}

TEST_CASE("to_string prints minimal parentheses") {
    const auto round = [](const std::string& text) { return ast::to_string(expr_ok(text)); };
    CHECK(round("((a + b)) * c") == "(a + b) * c");
    CHECK(round("a + (b * c)") == "a + b * c");
    CHECK(round("a - (b - c)") == "a - (b - c)");
    CHECK(round("a + (b + c)") == "a + (b + c)");
    CHECK(round("(a - b) - c") == "a - b - c");
    CHECK(round("a / (b * c)") == "a / (b * c)");
    CHECK(round("(a ^ b) ^ c") == "(a^b)^c");
    CHECK(round("a ^ (b ^ c)") == "a^b^c");
    CHECK(round("-(x^2)") == "-x^2");
    CHECK(round("(-x)^2") == "(-x)^2");
    CHECK(round("x^(-2)") == "x^-2");
    CHECK(round("-(a*b)") == "-(a * b)");
    CHECK(round("(-a)*b") == "-a * b");
    CHECK(round("(5) deg") == "5 deg");
    CHECK(round("(-5) deg") == "(-5) deg");
    CHECK(round("(a+b) deg") == "(a + b) deg");
    CHECK(round("x^(2 deg)") == "x^(2 deg)");
    CHECK(round("(x deg)^2") == "(x deg)^2");
    CHECK(round("((a, b)).x") == "(a, b).x");
    CHECK(round("(a+b).x") == "(a + b).x");
    CHECK(round("atan2(y, -x)") == "atan2(y, -x)");
    CHECK(round("q'' + q'") == "q'' + q'");
    CHECK(round("1e99999") == "1e99999");
}

TEST_CASE("to_string round-trips: printing and parsing again gives the same tree") {
    const char* cases[] = {
        "a + b * c - d / e",
        "-a^-b^c",
        "((a - b) - (c - d)) / -(e * f)",
        "2 * 5 deg + (x^2) deg",
        "-(-(-a))",
        "sin(x)^2 + cos(x)^2",
        "(1, -2, (3, 4)).y",
        "a / (b / c)",
        "(a + b)^(c + d)",
        "-(a - b).z",
        "x^-(y + 1)",
        "f(g(h(1)), (2, 3))",
        "a - b + c - (d + e)",
        "2^3^4 deg",
        "(-1)^n * t'",
    };
    for (const char* text : cases) {
        const ast::Expr first = expr_ok(text);
        const std::string printed = ast::to_string(first);
        CAPTURE(text);
        CAPTURE(printed);
        CHECK(sexpr(expr_ok(printed)) == sexpr(first));
    }
}
