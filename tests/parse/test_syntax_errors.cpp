// Syntax errors: the message says what was expected, the position is exact, parsing recovers
// and reports the errors of later lines too, and limits give Limit errors.
#include "parse_test_support.hpp"

#include <doctest/doctest.h>

using namespace yamsc;

namespace {

/// The diagnostics of a text that must fail to parse, as "L:C: message [kind]" lines.
std::string errors(const std::string& text) {
    test::Parsed r = test::parse_text(text);
    CHECK_FALSE(r.file.has_value());
    CHECK(r.diags.has_errors());
    return test::brief(r.diags);
}

} // namespace

TEST_CASE("errors in declarations") {
    CHECK(errors("model\n") ==
          "1:6: expected a model name after 'model', found end of line [syntax]\n");
    CHECK(errors("model m \"title\" x") == "1:17: expected end of statement, found 'x' [syntax]\n");
    CHECK(errors("model m \"no end\n") ==
          "1:16: unterminated string: expected '\"' before the end of the line [syntax]\n");
    CHECK(errors("model m \"a\\n\"") ==
          "1:11: unknown escape '\\n' in a string (only \\\" and \\\\ are allowed) [syntax]\n");
    CHECK(errors("param a 1") ==
          "1:9: expected '=' or ',' after parameter name, found '1' [syntax]\n");
    CHECK(errors("param = 1") == "1:7: expected a parameter name, found '=' [syntax]\n");
    CHECK(errors("param a =\n") == "1:10: expected an expression, found end of line [syntax]\n");
    CHECK(errors("param a = 1,") ==
          "1:13: expected a parameter name, found end of file [syntax]\n");
    CHECK(errors("input u order\n") ==
          "1:14: expected a whole number after 'order', found end of line [syntax]\n");
    CHECK(errors("input u order 1.5\n") ==
          "1:15: expected a whole number after 'order', found '1.5' [syntax]\n");
    CHECK(errors("input u order 99999999999\n") ==
          "1:15: order is too large (at most 2147483647) [limit]\n");
    CHECK(errors("dof q,, r") == "1:7: expected a DOF name, found ',' [syntax]\n");
    CHECK(errors("dof 1") == "1:5: expected a DOF name, found '1' [syntax]\n");
    CHECK(errors("gravity") == "1:8: expected an expression, found end of file [syntax]\n");
}

TEST_CASE("unknown statements suggest the keyword that was meant") {
    CHECK(errors("rigd nacelle {\n  mass = 1\n}\n") ==
          "1:1: unknown statement 'rigd' (did you mean 'rigid'?) [syntax]\n");
    CHECK(errors("  flexibel tower { }") ==
          "1:3: unknown statement 'flexibel' (did you mean 'flexible'?) [syntax]\n");
    CHECK(errors("lineraize { q = 0 }") ==
          "1:1: unknown statement 'lineraize' (did you mean 'linearize'?) [syntax]\n");
    CHECK(errors("Param a") == "1:1: unknown statement 'Param' (did you mean 'param'?) [syntax]\n");
    CHECK(errors("banana = 3") == "1:1: unknown statement 'banana' [syntax]\n");
    CHECK(errors("}") == "1:1: unexpected '}': no block is open [syntax]\n");
    CHECK(errors("joint a -> b\n{ rotate x q }") ==
          "2:1: unexpected '{': a block starts on the line of its statement [syntax]\n");
    CHECK(errors("$") == "1:1: expected a statement, found '$' [syntax]\n");
    CHECK(errors(std::string("dof q\n\0", 7)) ==
          "2:1: expected a statement, found byte 0x00 [syntax]\n");
    CHECK(errors("\xC3\xA9t\xC3\xA9") == "1:1: expected a statement, found '\xC3\xA9' [syntax]\n");
    CHECK(errors("\xFF") == "1:1: expected a statement, found byte 0xFF [syntax]\n");
}

TEST_CASE("errors in body blocks") {
    CHECK(errors("rigid { mass = 1 }") ==
          "1:7: expected a body name after 'rigid', found '{' [syntax]\n");
    CHECK(errors("rigid b mass = 1") ==
          "1:9: expected '{' after the body name, found 'mass' [syntax]\n");
    CHECK(errors("rigid b {\n  mass 5\n}") ==
          "2:8: expected '=' after property name 'mass', found '5' [syntax]\n");
    CHECK(errors("rigid b {\n  mass =\n}") ==
          "2:9: expected a value (an expression, a string or a table), found end of line "
          "[syntax]\n");
    CHECK(errors("rigid b {\n  = 5\n}") ==
          "2:3: expected a property 'name = value', found '=' [syntax]\n");
    CHECK(errors("rigid b {\n  mass = 1\n") ==
          "3:1: expected '}' to close the body block started at 1:9 [syntax]\n");
    CHECK(errors("rigid b {\n  mass = 1\ndof q\n") ==
          "3:1: expected '}' to close the body block started at 1:9 [syntax]\n");
    CHECK(errors("rigid b { mass = 1 2 }") ==
          "1:20: expected end of statement, found '2' [syntax]\n");
    CHECK(errors("rigid b { s = (0: 1, 1 2) }") ==
          "1:24: expected ':' between the station and its value, found '2' [syntax]\n");
    CHECK(errors("rigid b { s = (0: 1, 1: 2 }") ==
          "1:27: expected ',' or ')' to close the table started at 1:15, found '}' [syntax]\n");
    CHECK(errors("rigid b { s = (0: 1,) }") ==
          "1:21: expected 'station: value' in the table, found ')' [syntax]\n");
    CHECK(errors("flexible t {\n  symbolc modes = (q)\n}") ==
          "2:3: unknown item 'symbolc' (did you mean 'symbolic'?) [syntax]\n");
    CHECK(errors("flexible t {\n  symbolic (q)\n}") ==
          "2:12: expected 'modes = (...)' after 'symbolic', found '(' [syntax]\n");
    CHECK(errors("flexible t { modes = q }") ==
          "1:22: expected '(' and a list of modes, e.g. (q1, _, q2) or (flap1 -> q1), found 'q' "
          "[syntax]\n");
    CHECK(errors("flexible t { modes (q) }") ==
          "1:20: expected '=' after 'modes', found '(' [syntax]\n");
    CHECK(errors("flexible t { modes = (q1 q2) }") ==
          "1:26: expected ',' or ')' to close the list of modes started at 1:22, found 'q2' "
          "[syntax]\n");
    CHECK(errors("flexible t { modes = (q1, 3) }") ==
          "1:27: expected a DOF name, '_' or 'mode -> dof', found '3' [syntax]\n");
    CHECK(errors("flexible t { modes = (m1 -> ) }") ==
          "1:29: expected a DOF name after '->', found ')' [syntax]\n");
    CHECK(errors("flexible t { beam \"f\" fmt }") ==
          "1:27: expected '{' to start the beam block, found '}' [syntax]\n");
    CHECK(errors("flexible t { beam { length = 1 }\n beam { length = 2 } }") ==
          "2:2: flexible body 't' already has a beam (at 1:14) [syntax]\n");
}

TEST_CASE("errors in mode shapes") {
    const std::string head = "flexible t {\n  beam {\n";
    CHECK(errors(head + "    mode x = z^2\n  }\n}") ==
          "3:12: expected the direction x, y or z after the mode name, found '=' [syntax]\n");
    CHECK(errors(head + "    mode fa1 w = z^2\n  }\n}") ==
          "3:14: expected the direction x, y or z after the mode name, found 'w' [syntax]\n");
    CHECK(errors(head + "    mode fa1 x z^2\n  }\n}") ==
          "3:16: expected '=' after the mode direction, found 'z' [syntax]\n");
    CHECK(errors(head + "    mode = z^2\n  }\n}") ==
          "3:10: expected a mode name after 'mode', found '=' [syntax]\n");
    CHECK(errors(head + "    mode fa1 x = 0.5 z^2 +\n  }\n}") ==
          "3:27: expected an expression after the operator, found end of line [syntax]\n");
    CHECK(errors(head + "    mdoe fa1 x = z\n  }\n}") ==
          "3:5: unknown item 'mdoe' (did you mean 'mode'?) [syntax]\n");
}

TEST_CASE("errors in joints") {
    CHECK(errors("joint -> b") ==
          "1:7: expected the parent: ground, a body, body.tip or body.node(k), found '->' "
          "[syntax]\n");
    CHECK(errors("joint a b") ==
          "1:9: expected '->' between the parent and the child body, found 'b' [syntax]\n");
    CHECK(errors("joint a ->") ==
          "1:11: expected the child body name after '->', found end of file [syntax]\n");
    CHECK(errors("joint a.top -> b") ==
          "1:9: expected 'tip' or 'node(k)' after '.', found 'top' [syntax]\n");
    CHECK(errors("joint a.node 3 -> b") == "1:14: expected '(' after 'node', found '3' [syntax]\n");
    CHECK(errors("joint a.node(3 b) -> c") ==
          "1:16: expected ')' after the node number, found 'b' [syntax]\n");
    CHECK(errors("joint a -> b rotate x q") ==
          "1:14: expected '{' or end of statement after the child body, found 'rotate' "
          "[syntax]\n");
    CHECK(errors("joint a -> b {\n  rotat x psi\n}") ==
          "2:3: unknown joint step 'rotat' (did you mean 'rotate'?) [syntax]\n");
    CHECK(errors("joint a -> b {\n  spin x psi\n}") ==
          "2:3: unknown joint step 'spin': expected at, translate, rotate, free or "
          "'option = value' [syntax]\n");
    CHECK(errors("joint a -> b { 5 }") ==
          "1:16: expected a joint step (at, translate, rotate, free) or 'option = value', "
          "found '5' [syntax]\n");
    CHECK(errors("joint a -> b { rotate w psi }") ==
          "1:23: expected an axis: x, y, z, -x, -y, -z or a vector (a, b, c), found 'w' "
          "[syntax]\n");
    CHECK(errors("joint a -> b { rotate xx psi }") ==
          "1:23: expected an axis: x, y, z, -x, -y, -z or a vector (a, b, c), found 'xx' "
          "[syntax]\n");
    CHECK(errors("joint a -> b { translate x }") ==
          "1:28: expected an expression, found '}' [syntax]\n");
    CHECK(errors("joint a -> b { at }") == "1:19: expected an expression, found '}' [syntax]\n");
    CHECK(errors("joint a -> b { free x, y }") ==
          "1:21: expected '(' and six DOF names after 'free', found 'x' [syntax]\n");
    CHECK(errors("joint a -> b { free (x, y, z) }") ==
          "1:16: 'free' takes six DOF names (x, y, z, phi_x, phi_y, phi_z), found 3 [syntax]\n");
    CHECK(errors("joint a -> b { free (x, y 1) }") ==
          "1:27: expected ',' or ')' to close the list started at 1:21, found '1' [syntax]\n");
    CHECK(errors("joint a -> b {\n  rotate x psi\n") ==
          "3:1: expected '}' to close the joint block started at 1:14 [syntax]\n");
}

TEST_CASE("errors in loads, approximations, linearize, outputs and points") {
    CHECK(errors("force rotor = (1, 0, 0)") ==
          "1:7: expected 'on' after 'force', found 'rotor' [syntax]\n");
    CHECK(errors("force on = (1, 0, 0)") ==
          "1:10: expected a body name after 'on', found '=' [syntax]\n");
    CHECK(errors("force on rotor (1, 0, 0)") ==
          "1:16: expected 'at', 'in' or '=' in the force statement, found '(' [syntax]\n");
    CHECK(errors("force on rotor in = (1, 0, 0)") ==
          "1:19: expected a frame (a body or ground) after 'in', found '=' [syntax]\n");
    CHECK(errors("torque on rotor at (0,0,0) = (1, 0, 0)") ==
          "1:17: expected 'in' or '=' in the torque statement, found 'at' [syntax]\n");
    CHECK(errors("torque rotor = (1, 0, 0)") ==
          "1:8: expected 'on' after 'torque', found 'rotor' [syntax]\n");
    CHECK(errors("spring psi K") ==
          "1:12: expected 'stiffness' or 'damping' after the DOF name, found 'K' [syntax]\n");
    CHECK(errors("spring stiffness K") ==
          "1:18: expected 'stiffness' or 'damping' after the DOF name, found 'K' [syntax]\n");
    CHECK(errors("spring psi stiffness K stiffness K") ==
          "1:24: expected end of statement, found 'stiffness' [syntax]\n");
    CHECK(errors("genforce q f") == "1:12: expected '=' after the DOF name, found 'f' [syntax]\n");
    CHECK(errors("approx a order x") ==
          "1:16: expected a whole number after 'order', found 'x' [syntax]\n");
    CHECK(errors("approx order 2") == "1:14: expected end of statement, found '2' [syntax]\n");
    CHECK(errors("linearize q = 0") ==
          "1:11: expected '{' after 'linearize', found 'q' [syntax]\n");
    CHECK(errors("linearize { q 0 }") == "1:15: expected '=' after the name, found '0' [syntax]\n");
    CHECK(errors("linearize { q''' = 0 }") ==
          "1:16: too many primes: at most two (q'') are allowed [syntax]\n");
    CHECK(errors("linearize { 3 = 0 }") ==
          "1:13: expected 'name = value' in the linearize block, found '3' [syntax]\n");
    CHECK(errors("linearize { q = 0 }\nlinearize { q = 1 }") ==
          "2:1: duplicate 'linearize' block (the first is at 1:1) [syntax]\n");
    CHECK(errors("model a\nmodel b") ==
          "2:1: duplicate 'model' statement (the first is at 1:7) [syntax]\n");
    CHECK(errors("gravity (0,0,-g)\ngravity (0,0,g)") ==
          "2:1: duplicate 'gravity' statement (the first is at 1:1) [syntax]\n");
    CHECK(errors("output y q") == "1:10: expected '=' after the output name, found 'q' [syntax]\n");
    CHECK(errors("output = q") == "1:8: expected an output name, found '=' [syntax]\n");
    CHECK(errors("output y = q in") ==
          "1:16: expected a frame (a body or ground) after 'in', found end of file [syntax]\n");
    CHECK(errors("point p blade at (0, 0, 1)") ==
          "1:9: expected 'on' after the point name, found 'blade' [syntax]\n");
    CHECK(errors("point p on blade (0, 0, 1)") ==
          "1:18: expected 'at' after the body name, found '(' [syntax]\n");
}

TEST_CASE("recovery: every bad line is reported, good lines around them still parse") {
    const std::string text = "model m\n"               // 1
                             "param a 1\n"             // 2
                             "param b = 2\n"           // 3
                             "param c = )\n"           // 4
                             "rigd nacelle {\n"        // 5
                             "  mass = 1\n"            // 6
                             "}\n"                     // 7
                             "rigid hub {\n"           // 8
                             "  mass 5\n"              // 9
                             "  com = (1, 2\n"         // 10
                             "  inertia = (1, 2, 3)\n" // 11
                             "}\n"                     // 12
                             "joint ground -> hub {\n" // 13
                             "  rotat x psi\n"         // 14
                             "  rotate q psi\n"        // 15
                             "  rotate x psi\n"        // 16
                             "}\n"                     // 17
                             "dof x y; dof z\n"        // 18
                             "output w = 1 +\n";       // 19
    CHECK(errors(text) ==
          "2:9: expected '=' or ',' after parameter name, found '1' [syntax]\n"
          "4:11: expected an expression, found ')' [syntax]\n"
          "5:1: unknown statement 'rigd' (did you mean 'rigid'?) [syntax]\n"
          "9:8: expected '=' after property name 'mass', found '5' [syntax]\n"
          "11:3: expected ',' or ')' to close the '(' at 10:9, found 'inertia' [syntax]\n"
          "14:3: unknown joint step 'rotat' (did you mean 'rotate'?) [syntax]\n"
          "15:10: expected an axis: x, y, z, -x, -y, -z or a vector (a, b, c), found 'q' "
          "[syntax]\n"
          "18:7: expected end of statement, found 'y' [syntax]\n"
          "19:15: expected an expression after the operator, found end of line [syntax]\n");
}

TEST_CASE("recovery: an unclosed block ends at the next statement, which still parses") {
    test::Parsed r = test::parse_text("flexible f {\n"
                                      "  beam {\n"
                                      "    length = 2\n"
                                      "joint a -> b { rotate x q }\n"
                                      "param p q\n");
    CHECK_FALSE(r.file.has_value());
    CHECK(test::brief(r.diags) ==
          "4:1: expected '}' to close the beam block started at 2:8 [syntax]\n"
          "4:1: expected '}' to close the body block started at 1:12 [syntax]\n"
          "5:9: expected '=' or ',' after parameter name, found 'q' [syntax]\n");
}

TEST_CASE("recovery: a broken block header skips the whole block") {
    CHECK(errors("rigid {\n  mass = 1\n  com = (0, 0, 0)\n}\nparam a b\n") ==
          "1:7: expected a body name after 'rigid', found '{' [syntax]\n"
          "5:9: expected '=' or ',' after parameter name, found 'b' [syntax]\n");
}

TEST_CASE("recovery stops after 50 errors with a note") {
    std::string text;
    for (int i = 0; i < 80; ++i) text += "param a b\n";
    test::Parsed r = test::parse_text(text);
    CHECK_FALSE(r.file.has_value());
    CHECK(r.diags.error_count() == 50);
    REQUIRE(r.diags.all().size() == 51);
    CHECK(r.diags.all().back().severity == diag::Severity::note);
    CHECK(r.diags.all().back().message == "too many errors (50); stopping here");
    CHECK(r.diags.all()[49].loc.line == 50);
}

TEST_CASE("limits: nesting depth, expression depth, list length") {
    const std::string deep = "param a = " + std::string(300, '(') + "1" + std::string(300, ')');
    CHECK(errors(deep) == "1:211: expression is nested too deeply (more than 200 levels of "
                          "brackets, signs or powers) [limit]\n");
    CHECK(errors("param a = " + std::string(1000, '-') + "1") ==
          "1:211: expression is nested too deeply (more than 200 levels of brackets, signs or "
          "powers) [limit]\n");
    std::string power = "param a = x";
    for (int i = 0; i < 300; ++i) power += "^x";
    CHECK(errors(power).find("expression is nested too deeply") != std::string::npos);

    std::string sum = "param a = 1";
    for (int i = 0; i < 1200; ++i) sum += "+1";
    CHECK(errors(sum) ==
          "1:2010: expression is nested too deeply (more than 1000 levels of operations); split "
          "it with parameters or outputs [limit]\n");
    std::string sum_ok = "param a = 1";
    for (int i = 0; i < 900; ++i) sum_ok += "+1";
    CHECK(test::parse_text(sum_ok).file.has_value());

    std::string vec = "param a = (0";
    for (int i = 0; i < 10'000; ++i) vec += ",1";
    vec += ")";
    CHECK(errors(vec) == "1:11: list has more than 10000 elements [limit]\n");

    std::string lines(1'000'001, '\n');
    CHECK(errors(lines) == "1000001:1: the file has more than 1000000 lines [limit]\n");
}

TEST_CASE("a later parse of good text is not affected by errors in an earlier one") {
    CHECK_FALSE(test::parse_text("param a b").file.has_value());
    CHECK(test::parse_text("param a = b").file.has_value());
}

TEST_CASE("a file with more expression terms than the limit stops with one Limit error") {
    std::string text;
    for (int i = 0; i < 60'000; ++i) text += "param p = a*b + c*d + e*f + g*h + i*j\n"; // 19 terms
    test::Parsed r = test::parse_text(text);
    CHECK_FALSE(r.file.has_value());
    REQUIRE(r.diags.all().size() == 1);
    CHECK(r.diags.all()[0].kind == diag::Kind::Limit);
    CHECK(r.diags.all()[0].message ==
          "the model has too many expressions (more than 1000000 terms)");
    CHECK(r.diags.all()[0].loc.line == (1'000'000 + 1 + 18) / 19);
}

TEST_CASE("a parse error renders with the file, position, line and caret") {
    diag::Diagnostics diags;
    CHECK_FALSE(
        parse::parse_model(test::make_source("model m\n\tparam a 1\n", "turbine.mbd"), diags)
            .has_value());
    CHECK(diags.render() == "turbine.mbd:2:10: error: expected '=' or ',' after parameter name, "
                            "found '1' [syntax]\n"
                            "  \tparam a 1\n"
                            "  \t        ^\n");
}

TEST_CASE("errors reported before the parse do not make a good file fail") {
    diag::Diagnostics diags;
    diags.error(diag::Kind::Io, diag::Location{}, "something else");
    CHECK(parse::parse_model(test::make_source("dof q"), diags).has_value());
    CHECK(parse::parse_expression(test::make_source("1 + 2"), diags).has_value());
    CHECK(diags.error_count() == 1);
}

TEST_CASE("the remaining messages, each with its position") {
    CHECK(errors("input , a") == "1:7: expected an input name, found ',' [syntax]\n");
    CHECK(errors("flexible { }") ==
          "1:10: expected a body name after 'flexible', found '{' [syntax]\n");
    CHECK(errors("flexible f\n") == "1:11: expected '{' after the body name, found end of line "
                                    "[syntax]\n");
    CHECK(errors("joint a -> b { free (x, y, z, 1, 2, 3) }") ==
          "1:31: expected a DOF name or '_', found '1' [syntax]\n");
    CHECK(errors("joint a -> b { free (a, b, c, d, e, f, g) }") ==
          "1:40: 'free' takes six DOF names (x, y, z, phi_x, phi_y, phi_z), found more [syntax]\n");
    CHECK(errors("torque on = (0, 0, 1)") ==
          "1:11: expected a body name after 'on', found '=' [syntax]\n");
    CHECK(errors("torque on hub in = (0, 0, 1)") ==
          "1:18: expected a frame (a body or ground) after 'in', found '=' [syntax]\n");
    CHECK(errors("spring = 1") == "1:8: expected a DOF name after 'spring', found '=' [syntax]\n");
    CHECK(errors("genforce = 1") ==
          "1:10: expected a DOF name after 'genforce', found '=' [syntax]\n");
    CHECK(errors("approx 2") == "1:8: expected a name to approximate, found '2' [syntax]\n");
    CHECK(errors("approx a,") ==
          "1:10: expected a name to approximate, found end of file [syntax]\n");
    CHECK(errors("linearize {\n  q = 0\n") ==
          "3:1: expected '}' to close the linearize block started at 1:11 [syntax]\n");
    CHECK(errors("point = 1") == "1:7: expected a point name, found '=' [syntax]\n");
    CHECK(errors("point p on at (0, 0, 0)") ==
          "1:15: expected 'at' after the body name, found '(' [syntax]\n");
    CHECK(errors("point p on (0, 0, 0)") ==
          "1:12: expected a body name after 'on', found '(' [syntax]\n");
    CHECK(errors("model m \"a\\\xFF\"") ==
          "1:11: unknown escape in a string: '\\' followed by byte 0xFF [syntax]\n");
    CHECK(errors("model m \"a\\") ==
          "1:11: unterminated string: expected '\"' before the end of the line [syntax]\n");
}

TEST_CASE("limits of tables, lists of modes and the file size") {
    std::string table = "rigid b { t = (0: 0";
    for (int i = 0; i < 10'000; ++i) table += ", 1: 1";
    table += ") }";
    CHECK(errors(table).find("table has more than 10000 rows [limit]") != std::string::npos);

    std::string modes = "flexible f { modes = (q0";
    for (int i = 0; i < 10'000; ++i) modes += ", q";
    modes += ") }";
    CHECK(errors(modes).find("list has more than 10000 elements [limit]") != std::string::npos);

    std::string call = "param a = f(0";
    for (int i = 0; i < 10'000; ++i) call += ",1";
    call += ")";
    CHECK(errors(call) == "1:12: list has more than 10000 elements [limit]\n");

    test::Parsed big = test::parse_text(std::string((16u << 20) + 1, ' '));
    CHECK_FALSE(big.file.has_value());
    REQUIRE(big.diags.all().size() == 1);
    CHECK(big.diags.all()[0].kind == diag::Kind::Limit);
    CHECK(big.diags.all()[0].loc.line == 0);
    CHECK(big.diags.all()[0].message ==
          "the file is too large (16777217 bytes; the limit is 16 MiB)");
}

TEST_CASE("line ends: CR LF is a line break, the column of its error is that of the CR") {
    CHECK(errors("dof q\r\nparam a =\r\ndof r\r\n") ==
          "2:10: expected an expression, found end of line [syntax]\n");
    CHECK(errors("# c\r\nparam a = (1,\r\n 2\r\n") ==
          "4:1: expected ',' or ')' to close the '(' at 2:11, found end of file [syntax]\n");
    CHECK(errors("dof q\rdof r") == "1:6: expected end of statement, found byte 0x0D [syntax]\n");
}
