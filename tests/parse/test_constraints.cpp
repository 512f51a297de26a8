// `constraint KIND NAME { role = value ... }`: the AST it fills and its syntax errors.
#include "parse_test_support.hpp"

#include <doctest/doctest.h>

using namespace yamsc;
using test::brief;
using test::parse_text;

TEST_CASE("constraint: kind, name, roles and positions") {
    test::Parsed r = parse_text("model m\n"
                                "constraint loop closing { a = crank.tip; b = rocker_end\n"
                                "  joint = revolute; axis = y; components = (x, z)\n"
                                "  dependent = (th2, th3) }\n"
                                "constraint speed roll { value = x' - R*th' }\n");
    INFO(r.diags.render());
    REQUIRE(r.file.has_value());
    REQUIRE(r.diags.all().empty());
    REQUIRE(r.file->constraints.size() == 2);
    const ast::Constraint& c = r.file->constraints[0];
    CHECK(c.kind.name == "loop");
    CHECK(c.id.name == "closing");
    CHECK(c.loc.line == 2);
    CHECK(c.loc.col == 1);
    CHECK(c.id.loc.col == 17);
    CHECK(c.end.line == 4);
    REQUIRE(c.roles.size() == 6);
    CHECK(c.roles[0].key == "a");
    CHECK(ast::to_string(c.roles[0].value.expr) == "crank.tip");
    CHECK(c.roles[4].key == "components");
    CHECK(c.roles[4].value.expr.kind == ast::Expr::Kind::vector);
    CHECK(c.roles[5].loc.line == 4);
    CHECK(c.roles[5].loc.col == 3);
    const ast::Constraint& s = r.file->constraints[1];
    CHECK(s.kind.name == "speed");
    REQUIRE(s.roles.size() == 1);
    CHECK(s.roles[0].value.expr.kind == ast::Expr::Kind::sub);
}

TEST_CASE("constraint: syntax errors are located") {
    CHECK(brief(parse_text("model m\nconstraint\n").diags) ==
          "2:11: expected the kind of constraint after 'constraint', found end of line [syntax]\n");
    CHECK(brief(parse_text("model m\nconstraint loop { a = b }\n").diags) ==
          "2:17: expected a name for the constraint after its kind, found '{' [syntax]\n");
    CHECK(brief(parse_text("model m\nconstraint loop c a = b\n").diags) ==
          "2:19: expected '{' after the constraint's name, found 'a' [syntax]\n");
    CHECK(brief(parse_text("model m\nconstraint loop c { a b }\n").diags) ==
          "2:21: expected 'role = value' in the constraint, found 'a' [syntax]\n");
}
