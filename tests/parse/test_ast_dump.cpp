// ast::to_string and ast::dump on trees the parser would not produce (built by hand): they
// print something readable instead of failing.
#include "ast/ast.hpp"

#include <doctest/doctest.h>

using namespace yamsc::ast;

namespace {
Expr leaf(Expr::Kind kind, std::string text) {
    Expr e;
    e.kind = kind;
    e.text = std::move(text);
    return e;
}
Expr node(Expr::Kind kind, std::vector<Expr> args, std::string text = {}) {
    Expr e;
    e.kind = kind;
    e.text = std::move(text);
    e.args = std::move(args);
    return e;
}
} // namespace

TEST_CASE("to_string of hand-built trees") {
    const Expr a = leaf(Expr::Kind::name, "a");
    const Expr two = leaf(Expr::Kind::number, "2");
    CHECK(to_string(node(Expr::Kind::add, {a})) == "a + <missing>");
    CHECK(to_string(node(Expr::Kind::pow, {})) == "<missing>^<missing>");
    CHECK(to_string(node(Expr::Kind::neg, {node(Expr::Kind::neg, {two})})) == "--2");
    CHECK(to_string(node(Expr::Kind::sub, {a, node(Expr::Kind::neg, {a})})) == "a - -a");
    CHECK(to_string(node(Expr::Kind::deg, {node(Expr::Kind::deg, {two})})) == "(2 deg) deg");
    CHECK(to_string(node(Expr::Kind::call, {}, "time")) == "time()");
    Expr q = leaf(Expr::Kind::name, "q");
    q.primes = 2;
    CHECK(to_string(node(Expr::Kind::component, {q}, "z")) == "q''.z");
}

TEST_CASE("dump of an empty model and of optional parts left out") {
    CHECK(dump(ModelFile{}).empty());
    ModelFile f;
    f.model = Named{"m", {}, {}};
    Joint j;
    j.parent.body = "b";
    j.parent.kind = PointRef::Kind::node; // node without its number
    j.child = "c";
    f.joints.push_back(j);
    Spring s;
    s.dof.name = "q";
    f.springs.push_back(s);
    CHECK(dump(f) == "model m\njoint b.node() -> c\nspring q\n");
}
