// Every statement of the model language parses into the AST fields it should fill.
#include "parse_test_support.hpp"

#include <doctest/doctest.h>

using namespace yamsc;
using test::parse_text;

namespace {

/// Parses text that must be free of errors.
ast::ModelFile parse_ok(const std::string& text) {
    test::Parsed r = parse_text(text);
    INFO(r.diags.render());
    REQUIRE(r.file.has_value());
    REQUIRE(r.diags.all().empty());
    return std::move(*r.file);
}

std::string str(const ast::Expr& e) {
    return ast::to_string(e);
}

} // namespace

TEST_CASE("model: name, title and position") {
    const ast::ModelFile f = parse_ok("model nrel5mw \"NREL 5-MW \\\"land\\\" C:\\\\x\"\n");
    REQUIRE(f.model.has_value());
    CHECK(f.model->name == "nrel5mw");
    CHECK(f.model->loc.line == 1);
    CHECK(f.model->loc.col == 7);
    CHECK(f.title == "NREL 5-MW \"land\" C:\\x");
    CHECK(parse_ok("model m").title.empty());
}

TEST_CASE("param: several per line, optional defaults, positions") {
    const ast::ModelFile f = parse_ok("param g = 9.807\n"
                                      "param M_N = 2.4e5, x_NG = 1.9, z_NG = 1.75\n"
                                      "param L_T\n"
                                      "param a, b = -2.5e-3, c\n");
    REQUIRE(f.params.size() == 8);
    CHECK(f.params[0].id.name == "g");
    CHECK(str(*f.params[0].value) == "9.807");
    CHECK(f.params[1].id.name == "M_N");
    CHECK(f.params[1].value->text == "2.4e5");
    CHECK(f.params[3].id.name == "z_NG");
    CHECK(f.params[3].id.loc.line == 2);
    CHECK(f.params[3].id.loc.col == 32);
    CHECK(f.params[4].id.name == "L_T");
    CHECK_FALSE(f.params[4].value.has_value());
    CHECK_FALSE(f.params[5].value.has_value());
    CHECK(f.params[6].value->kind == ast::Expr::Kind::neg);
    CHECK(f.params[6].value->args[0].text == "2.5e-3");
    CHECK(f.params[7].id.name == "c");
}

TEST_CASE("input: lists and per-name order") {
    const ast::ModelFile f =
        parse_ok("input f_a, tau_a, tau_g\ninput theta_p order 2, u order 1\n");
    REQUIRE(f.inputs.size() == 5);
    CHECK(f.inputs[0].id.name == "f_a");
    CHECK(f.inputs[0].order == 0);
    CHECK(f.inputs[2].id.name == "tau_g");
    CHECK(f.inputs[3].id.name == "theta_p");
    CHECK(f.inputs[3].order == 2);
    CHECK(f.inputs[4].order == 1);
    CHECK(f.inputs[4].id.loc.col == 24);
}

TEST_CASE("dof: declaration order is kept") {
    const ast::ModelFile f = parse_ok("dof q, psi\ndof x");
    REQUIRE(f.dofs.size() == 3);
    CHECK(f.dofs[0].name == "q");
    CHECK(f.dofs[1].name == "psi");
    CHECK(f.dofs[1].loc.col == 8);
    CHECK(f.dofs[2].name == "x");
    CHECK(f.dofs[2].loc.line == 2);
}

TEST_CASE("gravity: a vector expression") {
    const ast::ModelFile f = parse_ok("\n  gravity (0, 0, -g)");
    REQUIRE(f.gravity.has_value());
    CHECK(f.gravity->kind == ast::Expr::Kind::vector);
    CHECK(str(*f.gravity) == "(0, 0, -g)");
    CHECK(f.gravity_loc.line == 2);
    CHECK(f.gravity_loc.col == 3);
}

TEST_CASE("rigid body: properties of every value kind") {
    const ast::ModelFile f =
        parse_ok("rigid nacelle {\n"
                 "    mass = M_N\n"
                 "    com = (x_NG, 0, z_NG)   # comment\n"
                 "    inertia = (Ixx, Iyy, Izz, Ixy, Iyz, Ixz); label = \"n\"\n"
                 "    stiff = (0: 1, 0.5: 2)\n"
                 "}\n");
    REQUIRE(f.rigid_bodies.size() == 1);
    const ast::RigidBody& b = f.rigid_bodies[0];
    CHECK(b.name == "nacelle");
    CHECK(b.loc.line == 1);
    CHECK(b.loc.col == 7);
    REQUIRE(b.properties.size() == 5);
    CHECK(b.properties[0].key == "mass");
    CHECK(b.properties[0].loc.line == 2);
    CHECK(b.properties[0].loc.col == 5);
    CHECK(b.properties[0].value.kind == ast::Value::Kind::expr);
    CHECK(b.properties[0].value.loc.col == 12);
    CHECK(str(b.properties[0].value.expr) == "M_N");
    CHECK(b.properties[1].value.expr.kind == ast::Expr::Kind::vector);
    CHECK(b.properties[1].value.expr.args.size() == 3);
    CHECK(b.properties[2].value.expr.args.size() == 6);
    CHECK(b.properties[3].key == "label");
    CHECK(b.properties[3].value.kind == ast::Value::Kind::string);
    CHECK(b.properties[3].value.str == "n");
    CHECK(b.properties[4].value.kind == ast::Value::Kind::table);
    REQUIRE(b.properties[4].value.table.size() == 2);
    CHECK(b.properties[4].value.table[1].station.text == "0.5");
    CHECK(b.properties[4].value.table[1].value.text == "2");
}

TEST_CASE("rigid body: one-line block and empty block") {
    const ast::ModelFile f = parse_ok("rigid a { mass = 1; com = (0, 0, 1) }\nrigid b {}\n");
    REQUIRE(f.rigid_bodies.size() == 2);
    CHECK(f.rigid_bodies[0].properties.size() == 2);
    CHECK(f.rigid_bodies[1].properties.empty());
}

TEST_CASE("flexible body from a SID file, with skipped modes and taylor order") {
    const ast::ModelFile f = parse_ok("flexible tower {\n"
                                      "    sid = \"nrel5mw_tower.sid\"\n"
                                      "    modes = (q1, _, q2)\n"
                                      "    taylor = 1\n"
                                      "}\n");
    REQUIRE(f.flexible_bodies.size() == 1);
    const ast::FlexibleBody& b = f.flexible_bodies[0];
    CHECK(b.name == "tower");
    CHECK_FALSE(b.symbolic);
    CHECK_FALSE(b.beam.has_value());
    REQUIRE(b.properties.size() == 3);
    CHECK(b.properties[0].value.str == "nrel5mw_tower.sid");
    CHECK(b.properties[1].key == "modes");
    CHECK(b.properties[1].value.kind == ast::Value::Kind::modes);
    REQUIRE(b.properties[1].value.modes.size() == 3);
    CHECK(b.properties[1].value.modes[0].dof == "q1");
    CHECK(b.properties[1].value.modes[0].mode.empty());
    CHECK(b.properties[1].value.modes[1].dof == "_");
    CHECK(b.properties[1].value.modes[2].dof == "q2");
    CHECK(b.properties[1].value.modes[2].loc.col == 21);
    CHECK(b.properties[1].value.loc.col == 13);
    CHECK(str(b.properties[2].value.expr) == "1");
}

TEST_CASE("flexible body with symbolic modes") {
    const ast::ModelFile f = parse_ok("flexible tower_sym { symbolic modes = (q1, q2) }");
    const ast::FlexibleBody& b = f.flexible_bodies.at(0);
    CHECK(b.symbolic);
    REQUIRE(b.properties.size() == 1);
    CHECK(b.properties[0].key == "modes");
    CHECK(b.properties[0].value.modes.size() == 2);
}

TEST_CASE("flexible body with a beam read from a file") {
    const ast::ModelFile f =
        parse_ok("flexible blade1 {\n"
                 "    beam \"NRELOffshrBsline5MW_Blade.dat\" elastodyn_blade {\n"
                 "        length = 61.5\n"
                 "        modes = (flap1 -> qf1, edge1 -> qe1,\n"
                 "                 flap2 -> qf2)\n"
                 "        stations = 50\n"
                 "    }\n"
                 "}\n");
    const ast::FlexibleBody& b = f.flexible_bodies.at(0);
    REQUIRE(b.beam.has_value());
    CHECK(b.properties.empty());
    CHECK(b.beam->file == std::optional<std::string>("NRELOffshrBsline5MW_Blade.dat"));
    CHECK(b.beam->format == "elastodyn_blade");
    CHECK(b.beam->loc.line == 2);
    CHECK(b.beam->loc.col == 5);
    REQUIRE(b.beam->properties.size() == 3);
    const std::vector<ast::ModeEntry>& modes = b.beam->properties[1].value.modes;
    REQUIRE(modes.size() == 3);
    CHECK(modes[0].mode == "flap1");
    CHECK(modes[0].dof == "qf1");
    CHECK(modes[2].mode == "flap2");
    CHECK(modes[2].dof == "qf2");
    CHECK(modes[2].loc.line == 5);
    CHECK(b.beam->properties[2].key == "stations");
}

TEST_CASE("flexible body with an inline beam: tables and polynomial mode shapes") {
    const ast::ModelFile f =
        parse_ok("flexible mast {\n"
                 "    beam {\n"
                 "        length = L; mass_per_length = (0: 5590.9, 1: 2536.3)\n"
                 "        EI_x = (0: 6.14e11,\n"
                 "                1: 1.16e11)\n"
                 "        mode fa1 x = 0.7004 z^2 + 2.1963 z^3 - 5.6202 z^4\n"
                 "        mode ss1 y = z^2 (1 - z) / 2\n"
                 "        modes = (fa1 -> q, ss1 -> r); damping_ratio = 0.01\n"
                 "    }\n"
                 "}\n");
    const ast::Beam& beam = *f.flexible_bodies.at(0).beam;
    CHECK_FALSE(beam.file.has_value());
    CHECK(beam.format.empty());
    REQUIRE(beam.properties.size() == 5);
    CHECK(beam.properties[1].key == "mass_per_length");
    REQUIRE(beam.properties[1].value.table.size() == 2);
    CHECK(beam.properties[1].value.table[0].station.text == "0");
    CHECK(beam.properties[1].value.table[0].value.text == "5590.9");
    CHECK(beam.properties[2].value.table[1].value.text == "1.16e11");
    CHECK(beam.properties[4].key == "damping_ratio");
    REQUIRE(beam.mode_shapes.size() == 2);
    CHECK(beam.mode_shapes[0].name == "fa1");
    CHECK(beam.mode_shapes[0].direction == "x");
    CHECK(beam.mode_shapes[0].loc.line == 6);
    CHECK(str(beam.mode_shapes[0].shape) == "0.7004 * z^2 + 2.1963 * z^3 - 5.6202 * z^4");
    // juxtaposition is a product: (0.7004 * z^2) + ...
    CHECK(beam.mode_shapes[0].shape.kind == ast::Expr::Kind::sub);
    CHECK(beam.mode_shapes[1].direction == "y");
    CHECK(str(beam.mode_shapes[1].shape) == "z^2 * (1 - z) / 2");
}

TEST_CASE("joints: parent points, steps, axes, options") {
    const ast::ModelFile f =
        parse_ok("joint ground -> tower\n"
                 "joint tower.tip -> nacelle { rotate y -theta_t }\n"
                 "joint nacelle -> rotor { at (x_NR, 0, z_NR); rotate x psi }\n"
                 "joint ground -> floater {\n"
                 "    translate -z surge\n"
                 "    rotate (0, 1, 0) pitch\n"
                 "}\n"
                 "joint blade.node(k + 1) -> tip { elastic_rotation = exact }\n"
                 "joint ground -> f6 { free (x, y, z, phi_x, _, phi_z) }\n");
    REQUIRE(f.joints.size() == 6);

    const ast::Joint& clamp = f.joints[0];
    CHECK(clamp.parent.body == "ground");
    CHECK(clamp.parent.kind == ast::PointRef::Kind::origin);
    CHECK(clamp.child == "tower");
    CHECK(clamp.child_loc.col == 17);
    CHECK(clamp.loc.col == 1);
    CHECK(clamp.steps.empty());

    const ast::Joint& tilt = f.joints[1];
    CHECK(tilt.parent.body == "tower");
    CHECK(tilt.parent.kind == ast::PointRef::Kind::tip);
    REQUIRE(tilt.steps.size() == 1);
    CHECK(tilt.steps[0].kind == ast::JointStep::Kind::rotate);
    CHECK(tilt.steps[0].axis.index == 1);
    CHECK(tilt.steps[0].axis.sign == 1);
    CHECK_FALSE(tilt.steps[0].axis.vector.has_value());
    CHECK(str(tilt.steps[0].arg) == "-theta_t");
    CHECK(tilt.steps[0].loc.col == 30);
    CHECK(tilt.steps[0].axis.loc.col == 37);

    const ast::Joint& rotor = f.joints[2];
    REQUIRE(rotor.steps.size() == 2);
    CHECK(rotor.steps[0].kind == ast::JointStep::Kind::at);
    CHECK(str(rotor.steps[0].vector) == "(x_NR, 0, z_NR)");
    CHECK(rotor.steps[1].axis.index == 0);
    CHECK(rotor.steps[1].arg.text == "psi");

    const ast::Joint& floater = f.joints[3];
    REQUIRE(floater.steps.size() == 2);
    CHECK(floater.steps[0].kind == ast::JointStep::Kind::translate);
    CHECK(floater.steps[0].axis.index == 2);
    CHECK(floater.steps[0].axis.sign == -1);
    CHECK(floater.steps[0].loc.line == 5);
    CHECK(str(*floater.steps[1].axis.vector) == "(0, 1, 0)");
    CHECK(floater.steps[1].arg.text == "pitch");

    const ast::Joint& node = f.joints[4];
    CHECK(node.parent.kind == ast::PointRef::Kind::node);
    CHECK(str(*node.parent.node) == "k + 1");
    REQUIRE(node.steps.size() == 1);
    CHECK(node.steps[0].kind == ast::JointStep::Kind::option);
    CHECK(node.steps[0].option.key == "elastic_rotation");
    CHECK(node.steps[0].option.value.expr.text == "exact");

    const ast::Joint& six = f.joints[5];
    REQUIRE(six.steps.size() == 1);
    CHECK(six.steps[0].kind == ast::JointStep::Kind::free);
    REQUIRE(six.steps[0].dofs.size() == 6);
    CHECK(six.steps[0].dofs[0].dof == "x");
    CHECK(six.steps[0].dofs[4].dof == "_");
    CHECK(six.steps[0].dofs[5].dof == "phi_z");
}

TEST_CASE("x, y and z are axes after rotate/translate but names in expressions") {
    const ast::ModelFile f = parse_ok("joint a -> b { translate x x; rotate y -y; rotate z x^2 }");
    const auto& steps = f.joints.at(0).steps;
    REQUIRE(steps.size() == 3);
    CHECK(steps[0].axis.index == 0);
    CHECK(steps[0].arg.kind == ast::Expr::Kind::name);
    CHECK(steps[0].arg.text == "x");
    CHECK(steps[1].axis.index == 1);
    CHECK(str(steps[1].arg) == "-y");
    CHECK(str(steps[2].arg) == "x^2");
}

TEST_CASE("force and torque: optional point and frame") {
    const ast::ModelFile f = parse_ok("force  on rotor at (0, 0, 0) in nacelle = (f_a, 0, 0)\n"
                                      "force on floater = (0, 0, F_B)\n"
                                      "force on hub in ground = (0, 0, 1)\n"
                                      "torque on rotor in nacelle = (tau_a - tau_g, 0, 0)\n"
                                      "torque on rotor = (0, 0, T)\n");
    REQUIRE(f.forces.size() == 3);
    CHECK(f.forces[0].body == "rotor");
    CHECK(f.forces[0].body_loc.col == 11);
    CHECK(str(*f.forces[0].at) == "(0, 0, 0)");
    CHECK(f.forces[0].frame->name == "nacelle");
    CHECK(f.forces[0].frame->loc.col == 33);
    CHECK(str(f.forces[0].value) == "(f_a, 0, 0)");
    CHECK_FALSE(f.forces[1].at.has_value());
    CHECK_FALSE(f.forces[1].frame.has_value());
    CHECK_FALSE(f.forces[2].at.has_value());
    CHECK(f.forces[2].frame->name == "ground");
    REQUIRE(f.torques.size() == 2);
    CHECK(f.torques[0].frame->name == "nacelle");
    CHECK(str(f.torques[0].value) == "(tau_a - tau_g, 0, 0)");
    CHECK(f.torques[0].loc.line == 4);
    CHECK_FALSE(f.torques[1].frame.has_value());
}

TEST_CASE("spring: stiffness, damping, or both in either order") {
    const ast::ModelFile f = parse_ok("spring psi stiffness K_s damping D_s\n"
                                      "spring q stiffness 2*K\n"
                                      "spring r damping D\n"
                                      "spring s damping D stiffness K\n");
    REQUIRE(f.springs.size() == 4);
    CHECK(f.springs[0].dof.name == "psi");
    CHECK(f.springs[0].dof.loc.col == 8);
    CHECK(str(*f.springs[0].stiffness) == "K_s");
    CHECK(str(*f.springs[0].damping) == "D_s");
    CHECK(str(*f.springs[1].stiffness) == "2 * K");
    CHECK_FALSE(f.springs[1].damping.has_value());
    CHECK_FALSE(f.springs[2].stiffness.has_value());
    CHECK(str(*f.springs[2].damping) == "D");
    CHECK(str(*f.springs[3].stiffness) == "K");
    CHECK(str(*f.springs[3].damping) == "D");
}

TEST_CASE("genforce, approx, linearize, output, point") {
    const ast::ModelFile f = parse_ok("genforce q = f_e\n"
                                      "approx theta_t order 1\n"
                                      "approx q, psi order 2\n"
                                      "approx a\n"
                                      "linearize { q = 0; psi = 0; psi' = Omega; q'' = 1\n"
                                      "            f_a = 0 }\n"
                                      "output tt_disp = position(nacelle).x in ground\n"
                                      "output rotor_speed = psi'\n"
                                      "point tip_pt on blade at (0, 0, L)\n");
    REQUIRE(f.genforces.size() == 1);
    CHECK(f.genforces[0].dof.name == "q");
    CHECK(f.genforces[0].value.text == "f_e");

    REQUIRE(f.approximations.size() == 3);
    CHECK(f.approximations[0].symbols.at(0).name == "theta_t");
    CHECK(f.approximations[0].order == 1);
    CHECK(f.approximations[1].symbols.size() == 2);
    CHECK(f.approximations[1].symbols[1].name == "psi");
    CHECK(f.approximations[1].order == 2);
    CHECK(f.approximations[2].order == 1);

    REQUIRE(f.linearize.has_value());
    CHECK(f.linearize->loc.line == 5);
    const auto& point = f.linearize->point;
    REQUIRE(point.size() == 5);
    CHECK(point[0].name == "q");
    CHECK(point[0].primes == 0);
    CHECK(point[2].name == "psi");
    CHECK(point[2].primes == 1);
    CHECK(point[2].value.text == "Omega");
    CHECK(point[3].primes == 2);
    CHECK(point[4].name == "f_a");
    CHECK(point[4].loc.line == 6);

    REQUIRE(f.outputs.size() == 2);
    CHECK(f.outputs[0].id.name == "tt_disp");
    CHECK(f.outputs[0].value.kind == ast::Expr::Kind::component);
    CHECK(f.outputs[0].value.text == "x");
    CHECK(f.outputs[0].value.args.at(0).kind == ast::Expr::Kind::call);
    CHECK(f.outputs[0].value.args.at(0).text == "position");
    CHECK(f.outputs[0].frame->name == "ground");
    CHECK(f.outputs[1].value.primes == 1);
    CHECK_FALSE(f.outputs[1].frame.has_value());

    REQUIRE(f.points.size() == 1);
    CHECK(f.points[0].id.name == "tip_pt");
    CHECK(f.points[0].body == "blade");
    CHECK(f.points[0].body_loc.col == 17);
    CHECK(str(f.points[0].at) == "(0, 0, L)");
}

TEST_CASE("comments, semicolons, blank lines, CRLF and a byte order mark") {
    const ast::ModelFile f =
        parse_ok("\xEF\xBB\xBF# header\r\n\r\nmodel m;dof q ; dof r\r\n  # indented comment\r\n"
                 "rigid b {\r\n  mass = 1\r\n}\r\n");
    CHECK(f.model->name == "m");
    REQUIRE(f.dofs.size() == 2);
    CHECK(f.dofs[1].loc.line == 3);
    CHECK(f.dofs[1].loc.col == 21);
    CHECK(f.rigid_bodies.at(0).properties.size() == 1);
}

TEST_CASE("a trailing comment documents the declarations of its own line") {
    const ast::ModelFile f = parse_ok("param a = 1, b = 2   #   both documented  \n"
                                      "param c = 3\n"
                                      "# a comment on its own line documents nothing\n"
                                      "param d\n"
                                      "input u order 2  # an input\n"
                                      "dof q, r # coordinates\n"
                                      "output y = q in ground # an output\n"
                                      "param e; param f # only f\n");
    REQUIRE(f.params.size() == 6);
    CHECK(f.params[0].id.doc == "both documented");
    CHECK(f.params[1].id.doc == "both documented");
    CHECK(f.params[2].id.doc.empty());
    CHECK(f.params[3].id.doc.empty());
    CHECK(f.params[4].id.doc.empty());
    CHECK(f.params[5].id.doc == "only f");
    CHECK(f.inputs.at(0).id.doc == "an input");
    CHECK(f.dofs.at(0).doc == "coordinates");
    CHECK(f.dofs.at(1).doc == "coordinates");
    CHECK(f.outputs.at(0).id.doc == "an output");
}

TEST_CASE("an empty file and a file of comments parse to an empty model") {
    for (const char* text : {"", "\n\n", "# only a comment", "  ;;  \n;"}) {
        const ast::ModelFile f = parse_ok(text);
        CHECK_FALSE(f.model.has_value());
        CHECK(f.params.empty());
        CHECK(f.source.get() != nullptr);
    }
}

TEST_CASE("load: kind, name, roles as properties, the statement's extent") {
    const ast::ModelFile f = parse_ok("model m\n"
                                      "load rotor_table aero {   # a comment\n"
                                      "    wind = V; pitch = beta\n"
                                      "    radius = R\n"
                                      "}\n");
    REQUIRE(f.loads.size() == 1);
    const ast::Load& l = f.loads[0];
    CHECK(l.kind.name == "rotor_table");
    CHECK(l.kind.loc.col == 6);
    CHECK(l.id.name == "aero");
    CHECK(l.loc.line == 2);
    CHECK(l.loc.col == 1);
    CHECK(l.end.line == 5);
    CHECK(l.end.col == 1);
    REQUIRE(l.roles.size() == 3);
    CHECK(l.roles[0].key == "wind");
    CHECK(str(l.roles[0].value.expr) == "V");
    CHECK(l.roles[1].key == "pitch");
    CHECK(l.roles[2].key == "radius");
    CHECK(l.roles[2].loc.line == 4);
}
