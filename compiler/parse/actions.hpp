#pragma once
// The grammar actions: each fills the ParseState when its rule has matched. Expressions are
// built on a stack (operands first, the operator's action combines them); declarations are
// appended to the ModelFile as soon as their name is read, and later actions fill in the rest.
// The grammar never backtracks over a rule with an action once it matched, so no action has to
// be undone (except after an error, which ParseState::rollback handles).
#include "grammar/model_grammar.hpp"
#include "parse/parse_state.hpp"

#include <tao/pegtl.hpp>

#include <climits>
#include <string>

namespace yamsc::parse {

namespace g = grammar;
using ExprKind = ast::Expr::Kind;

/// `\"` and `\\` resolved (the grammar admits no other escapes).
std::string unescape(std::string_view body);
/// A whole number for `order`; a Limit error if it does not fit an int.
int parse_order(const std::string& digits, const tao::pegtl::position& where, const ParseState& st);
/// A trailing comment without `#` and surrounding blanks.
std::string comment_text(std::string_view comment);

template <class Rule> struct action : tao::pegtl::nothing<Rule> {};

/// Declares `action<Rule>` with an apply() whose body sees `in` and `st`.
#define YAMSC_ACTION(RULE)                                                                         \
    template <> struct action<g::RULE> {                                                           \
        template <class Input> static void apply(const Input& in, ParseState& st);                 \
    };                                                                                             \
    template <class Input>                                                                         \
    void action<g::RULE>::apply([[maybe_unused]] const Input& in, [[maybe_unused]] ParseState& st)

/// The same for a rule template over expression contexts.
#define YAMSC_CONTEXT_ACTION(RULE)                                                                 \
    template <class C> struct action<g::RULE<C>> {                                                 \
        template <class Input> static void apply(const Input& in, ParseState& st);                 \
    };                                                                                             \
    template <class C>                                                                             \
    template <class Input>                                                                         \
    void action<g::RULE<C>>::apply([[maybe_unused]] const Input& in,                               \
                                   [[maybe_unused]] ParseState& st)

// ---------------------------------------------------------------- lexical

YAMSC_ACTION(string_body) {
    st.string_value = unescape(in.string_view());
}

YAMSC_ACTION(trailing_comment) {
    st.document(comment_text(in.string_view()));
}

// ---------------------------------------------------------------- expressions

YAMSC_ACTION(number_literal) {
    st.push_leaf(ExprKind::number, in.string(), in.position());
}
YAMSC_ACTION(expr_name) {
    st.push_leaf(ExprKind::name, in.string(), in.position());
}
YAMSC_ACTION(expr_primes) {
    if (in.size() > 0) st.top().primes = static_cast<int>(in.size());
}
YAMSC_ACTION(call_open) {
    st.open_list();
}
YAMSC_CONTEXT_ACTION(call_paren) {
    st.finish_call(in.position());
}
YAMSC_ACTION(paren_open) {
    st.open_list();
}
YAMSC_CONTEXT_ACTION(paren_group) {
    st.finish_group(in.position());
}
YAMSC_ACTION(component) {
    st.wrap_top(ExprKind::component, in.position(), std::string(1, in.string_view().back()));
}
YAMSC_ACTION(section_tip) {
    st.wrap_top(ExprKind::section, in.position(), "tip");
    st.top().loc = st.top().args[0].loc; // `tower.tip` is where `tower` is
}
YAMSC_CONTEXT_ACTION(section_node) {
    st.combine_top(ExprKind::section, in.position());
    st.top().text = "node";
    st.top().loc = st.top().args[0].loc;
}
YAMSC_CONTEXT_ACTION(pow_op) {
    st.combine_top(ExprKind::pow, in.position());
}
YAMSC_CONTEXT_ACTION(exponent_neg) {
    st.wrap_top(ExprKind::neg, in.position());
}
YAMSC_ACTION(deg_op) {
    st.wrap_top(ExprKind::deg, in.position());
}
YAMSC_CONTEXT_ACTION(negation) {
    st.wrap_top(ExprKind::neg, in.position());
}
YAMSC_CONTEXT_ACTION(mul_op) {
    st.combine_top(ExprKind::mul, in.position());
}
YAMSC_CONTEXT_ACTION(div_op) {
    st.combine_top(ExprKind::div, in.position());
}
YAMSC_CONTEXT_ACTION(juxtaposed) {
    st.combine_top(ExprKind::mul, in.position());
}
YAMSC_CONTEXT_ACTION(add_op) {
    st.combine_top(ExprKind::add, in.position());
}
YAMSC_CONTEXT_ACTION(sub_op) {
    st.combine_top(ExprKind::sub, in.position());
}

// ---------------------------------------------------------------- property values

YAMSC_ACTION(property_key) {
    st.property = ast::Property{};
    st.property.key = in.string();
    st.property.loc = st.loc(in.position());
}
YAMSC_ACTION(value_string) {
    st.property.value.kind = ast::Value::Kind::string;
    st.property.value.str = st.string_value;
}
YAMSC_ACTION(table_open) {
    st.table.clear();
}
YAMSC_ACTION(table_entry) {
    ast::TablePoint point;
    point.value = st.pop();
    point.station = st.pop();
    st.table.push_back(std::move(point));
    if (st.table.size() > Limits::max_list_length) {
        st.fail("table has more than " + std::to_string(Limits::max_list_length) + " rows",
                in.position(), diag::Kind::Limit);
    }
}
YAMSC_ACTION(value_table) {
    st.property.value.kind = ast::Value::Kind::table;
    st.property.value.table = std::move(st.table);
    st.table.clear();
}
YAMSC_ACTION(value_expression) {
    st.property.value.kind = ast::Value::Kind::expr;
    st.property.value.expr = st.pop();
}
YAMSC_ACTION(value) {
    st.property.value.loc = st.loc(in.position());
}
YAMSC_ACTION(property) {
    st.property_sinks.back()->push_back(std::move(st.property));
}

YAMSC_ACTION(mode_list_open) {
    st.entries.clear();
    st.list_loc = st.loc(in.position());
}
YAMSC_ACTION(mode_entry_name) {
    ast::ModeEntry entry;
    entry.dof = in.string();
    entry.loc = st.loc(in.position());
    st.entries.push_back(std::move(entry));
    if (st.entries.size() > Limits::max_list_length) {
        st.fail("list has more than " + std::to_string(Limits::max_list_length) + " elements",
                in.position(), diag::Kind::Limit);
    }
}
YAMSC_ACTION(mode_entry_dof) {
    ast::ModeEntry& entry = st.entries.back();
    entry.mode = std::move(entry.dof);
    entry.dof = in.string();
}
YAMSC_ACTION(modes_property) {
    ast::Property modes;
    modes.key = "modes";
    modes.loc = st.loc(in.position());
    modes.value.kind = ast::Value::Kind::modes;
    modes.value.modes = std::move(st.entries);
    modes.value.loc = st.list_loc;
    st.entries.clear();
    st.property_sinks.back()->push_back(std::move(modes));
}

// ---------------------------------------------------------------- declarations

YAMSC_ACTION(kw_model) {
    if (st.file.model) {
        st.fail("duplicate 'model' statement (the first is at " + line_col(st.file.model->loc) +
                    ")",
                in.position());
    }
    st.file.model.emplace();
}
YAMSC_ACTION(model_name) {
    st.file.model->name = in.string();
    st.file.model->loc = st.loc(in.position());
}
YAMSC_ACTION(model_title) {
    st.file.title = st.string_value;
}

YAMSC_ACTION(param_name) {
    ast::Param& param = st.file.params.emplace_back();
    param.id.name = in.string();
    param.id.loc = st.loc(in.position());
    st.doc_targets.push_back({ParseState::DocKind::param, st.file.params.size() - 1});
}
YAMSC_ACTION(param_value) {
    st.file.params.back().value = st.pop();
}

YAMSC_ACTION(input_name) {
    ast::Input& input = st.file.inputs.emplace_back();
    input.id.name = in.string();
    input.id.loc = st.loc(in.position());
    st.doc_targets.push_back({ParseState::DocKind::input, st.file.inputs.size() - 1});
}
YAMSC_ACTION(input_order) {
    st.file.inputs.back().order = parse_order(in.string(), in.position(), st);
}

YAMSC_ACTION(dof_name) {
    ast::Named& dof = st.file.dofs.emplace_back();
    dof.name = in.string();
    dof.loc = st.loc(in.position());
    st.doc_targets.push_back({ParseState::DocKind::dof, st.file.dofs.size() - 1});
}

YAMSC_ACTION(kw_gravity) {
    if (st.file.gravity_loc.line != 0) {
        st.fail("duplicate 'gravity' statement (the first is at " + line_col(st.file.gravity_loc) +
                    ")",
                in.position());
    }
    st.file.gravity_loc = st.loc(in.position());
}
YAMSC_ACTION(gravity_value) {
    st.file.gravity = st.pop();
}

// ---------------------------------------------------------------- bodies

YAMSC_ACTION(rigid_name) {
    ast::RigidBody& body = st.file.rigid_bodies.emplace_back();
    body.name = in.string();
    body.loc = st.loc(in.position());
}
YAMSC_ACTION(rigid_open) {
    st.property_sinks.push_back(&st.file.rigid_bodies.back().properties);
}
YAMSC_ACTION(rigid_close) {
    st.property_sinks.pop_back();
}

YAMSC_ACTION(flexible_name) {
    ast::FlexibleBody& body = st.file.flexible_bodies.emplace_back();
    body.name = in.string();
    body.loc = st.loc(in.position());
}
YAMSC_ACTION(flexible_open) {
    st.property_sinks.push_back(&st.file.flexible_bodies.back().properties);
}
YAMSC_ACTION(flexible_close) {
    st.property_sinks.pop_back();
}
YAMSC_ACTION(kw_symbolic) {
    st.file.flexible_bodies.back().symbolic = true;
}

YAMSC_ACTION(kw_beam) {
    ast::FlexibleBody& body = st.file.flexible_bodies.back();
    if (body.beam) {
        st.fail("flexible body '" + body.name + "' already has a beam (at " +
                    line_col(body.beam->loc) + ")",
                in.position());
    }
    body.beam.emplace().loc = st.loc(in.position());
}
YAMSC_ACTION(beam_file) {
    st.file.flexible_bodies.back().beam->file = st.string_value;
}
YAMSC_ACTION(beam_format) {
    st.file.flexible_bodies.back().beam->format = in.string();
}
YAMSC_ACTION(beam_open) {
    st.property_sinks.push_back(&st.file.flexible_bodies.back().beam->properties);
}
YAMSC_ACTION(beam_close) {
    st.property_sinks.pop_back();
}
YAMSC_ACTION(mode_shape_name) {
    ast::ModeShape& shape = st.file.flexible_bodies.back().beam->mode_shapes.emplace_back();
    shape.name = in.string();
    shape.loc = st.loc(in.position());
}
YAMSC_ACTION(mode_direction) {
    st.file.flexible_bodies.back().beam->mode_shapes.back().direction = in.string();
}
YAMSC_ACTION(mode_shape_value) {
    st.file.flexible_bodies.back().beam->mode_shapes.back().shape = st.pop();
}

// ---------------------------------------------------------------- joints

YAMSC_ACTION(kw_joint) {
    st.file.joints.emplace_back().loc = st.loc(in.position());
}
YAMSC_ACTION(parent_body) {
    ast::PointRef& parent = st.file.joints.back().parent;
    parent.body = in.string();
    parent.loc = st.loc(in.position());
}
YAMSC_ACTION(parent_tip) {
    st.file.joints.back().parent.kind = ast::PointRef::Kind::tip;
}
YAMSC_ACTION(node_number) {
    ast::PointRef& parent = st.file.joints.back().parent;
    parent.kind = ast::PointRef::Kind::node;
    parent.node = st.pop();
}
YAMSC_ACTION(joint_child) {
    st.file.joints.back().child = in.string();
    st.file.joints.back().child_loc = st.loc(in.position());
}
YAMSC_ACTION(at_step) {
    ast::JointStep& step = st.file.joints.back().steps.emplace_back();
    step.kind = ast::JointStep::Kind::at;
    step.vector = st.pop();
    step.loc = st.loc(in.position());
}
YAMSC_ACTION(axis_name) {
    const std::string text = in.string();
    st.axis = ast::Axis{};
    st.axis.sign = text[0] == '-' ? -1 : 1;
    st.axis.index = text.back() - 'x';
    st.axis.loc = st.loc(in.position());
}
YAMSC_ACTION(axis_vector) {
    st.axis = ast::Axis{};
    st.axis.vector = st.pop();
    st.axis.loc = st.loc(in.position());
}

template <ast::JointStep::Kind K> struct axis_step_action {
    template <class Input> static void apply(const Input& in, ParseState& st) {
        ast::JointStep& step = st.file.joints.back().steps.emplace_back();
        step.kind = K;
        step.axis = std::move(st.axis);
        step.arg = st.pop();
        step.loc = st.loc(in.position());
    }
};
template <> struct action<g::translate_step> : axis_step_action<ast::JointStep::Kind::translate> {};
template <> struct action<g::rotate_step> : axis_step_action<ast::JointStep::Kind::rotate> {};

YAMSC_ACTION(free_list_open) {
    st.entries.clear();
    st.list_loc = st.loc(in.position());
}
YAMSC_ACTION(free_name) {
    ast::ModeEntry entry;
    entry.dof = in.string();
    entry.loc = st.loc(in.position());
    st.entries.push_back(std::move(entry));
    if (st.entries.size() > 6) {
        st.fail("'free' takes six DOF names (x, y, z, phi_x, phi_y, phi_z), found more",
                in.position());
    }
}
YAMSC_ACTION(free_step) {
    if (st.entries.size() != 6) {
        st.fail("'free' takes six DOF names (x, y, z, phi_x, phi_y, phi_z), found " +
                    std::to_string(st.entries.size()),
                in.position());
    }
    ast::JointStep& step = st.file.joints.back().steps.emplace_back();
    step.kind = ast::JointStep::Kind::free;
    step.dofs = std::move(st.entries);
    step.loc = st.loc(in.position());
    st.entries.clear();
}
YAMSC_ACTION(joint_option) {
    ast::JointStep& step = st.file.joints.back().steps.emplace_back();
    step.kind = ast::JointStep::Kind::option;
    step.loc = st.property.loc;
    step.option = std::move(st.property);
}

// ---------------------------------------------------------------- loads

YAMSC_ACTION(kw_force) {
    st.file.forces.emplace_back().loc = st.loc(in.position());
}
YAMSC_ACTION(force_body) {
    st.file.forces.back().body = in.string();
    st.file.forces.back().body_loc = st.loc(in.position());
}
YAMSC_ACTION(force_at_value) {
    st.file.forces.back().at = st.pop();
}
YAMSC_ACTION(force_frame) {
    st.file.forces.back().frame = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(force_value) {
    st.file.forces.back().value = st.pop();
}

YAMSC_ACTION(kw_torque) {
    st.file.torques.emplace_back().loc = st.loc(in.position());
}
YAMSC_ACTION(torque_body) {
    st.file.torques.back().body = in.string();
    st.file.torques.back().body_loc = st.loc(in.position());
}
YAMSC_ACTION(torque_frame) {
    st.file.torques.back().frame = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(torque_value) {
    st.file.torques.back().value = st.pop();
}

YAMSC_ACTION(kw_spring) {
    st.file.springs.emplace_back().loc = st.loc(in.position());
}
YAMSC_ACTION(spring_dof) {
    st.file.springs.back().dof = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(stiffness_value) {
    st.file.springs.back().stiffness = st.pop();
}
YAMSC_ACTION(damping_value) {
    st.file.springs.back().damping = st.pop();
}

YAMSC_ACTION(kw_genforce) {
    st.file.genforces.emplace_back().loc = st.loc(in.position());
}
YAMSC_ACTION(genforce_dof) {
    st.file.genforces.back().dof = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(genforce_value) {
    st.file.genforces.back().value = st.pop();
}

// ---------------------------------------------------------------- external functions

YAMSC_ACTION(kw_external) {
    st.file.externals.emplace_back().loc = st.loc(in.position());
}
YAMSC_ACTION(ext_force_word) {
    st.file.externals.back().kind = ast::External::Kind::force;
}
YAMSC_ACTION(ext_torque_word) {
    st.file.externals.back().kind = ast::External::Kind::torque;
}
YAMSC_ACTION(ext_genforce_word) {
    st.file.externals.back().kind = ast::External::Kind::genforce;
}
YAMSC_ACTION(ext_body) {
    st.file.externals.back().body = in.string();
    st.file.externals.back().body_loc = st.loc(in.position());
}
YAMSC_ACTION(ext_at_value) {
    st.file.externals.back().at = st.pop();
}
YAMSC_ACTION(ext_frame) {
    st.file.externals.back().frame = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(ext_dof) {
    st.file.externals.back().dofs.push_back(ast::Named{in.string(), st.loc(in.position()), {}});
}
YAMSC_ACTION(ext_function) {
    st.file.externals.back().function = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(ext_arg_value) {
    st.file.externals.back().args.push_back(ast::ExternalArg{st.pop(), std::nullopt});
}
YAMSC_ACTION(ext_arg_frame) {
    st.file.externals.back().args.back().frame = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(ext_without) {
    st.file.externals.back().without_jacobian = true;
}

// ---------------------------------------------------------------- analysis

YAMSC_ACTION(kw_approx) {
    st.file.approximations.emplace_back().loc = st.loc(in.position());
}
YAMSC_ACTION(approx_symbol) {
    st.file.approximations.back().symbols.push_back(
        ast::Named{in.string(), st.loc(in.position()), {}});
}
YAMSC_ACTION(approx_order) {
    st.file.approximations.back().order = parse_order(in.string(), in.position(), st);
}

YAMSC_ACTION(kw_linearize) {
    if (st.file.linearize) {
        st.fail("duplicate 'linearize' block (the first is at " + line_col(st.file.linearize->loc) +
                    ")",
                in.position());
    }
    st.file.linearize.emplace().loc = st.loc(in.position());
    st.assignments = &st.file.linearize->point;
}
YAMSC_ACTION(kw_initial) {
    if (st.file.initial) {
        st.fail("duplicate 'initial' block (the first is at " + line_col(st.file.initial->loc) +
                    ")",
                in.position());
    }
    st.file.initial.emplace().loc = st.loc(in.position());
    st.assignments = &st.file.initial->state;
}
YAMSC_ACTION(assignment_name) {
    ast::Assignment& a = st.assignments->emplace_back();
    a.name = in.string();
    a.loc = st.loc(in.position());
}
YAMSC_ACTION(assignment_primes) {
    st.assignments->back().primes = static_cast<int>(in.size());
}
YAMSC_ACTION(assignment_value) {
    st.assignments->back().value = st.pop();
}

YAMSC_ACTION(kw_output) {
    st.file.outputs.emplace_back().loc = st.loc(in.position());
}
YAMSC_ACTION(output_name) {
    st.file.outputs.back().id = ast::Named{in.string(), st.loc(in.position()), {}};
    st.doc_targets.push_back({ParseState::DocKind::output, st.file.outputs.size() - 1});
}
YAMSC_ACTION(output_value) {
    st.file.outputs.back().value = st.pop();
}
YAMSC_ACTION(output_frame) {
    st.file.outputs.back().frame = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(output_frame_tip) {
    st.file.outputs.back().frame_point.kind = ast::PointRef::Kind::tip;
    st.file.outputs.back().frame_point.loc = st.loc(in.position());
}
YAMSC_ACTION(output_frame_node) {
    ast::PointRef& point = st.file.outputs.back().frame_point;
    point.kind = ast::PointRef::Kind::node;
    point.node = st.pop();
    point.loc = point.node->loc;
}

YAMSC_ACTION(kw_point) {
    st.file.points.emplace_back();
}
YAMSC_ACTION(point_name) {
    st.file.points.back().id = ast::Named{in.string(), st.loc(in.position()), {}};
    st.doc_targets.push_back({ParseState::DocKind::point, st.file.points.size() - 1});
}
YAMSC_ACTION(point_body) {
    st.file.points.back().body = in.string();
    st.file.points.back().body_loc = st.loc(in.position());
}
YAMSC_ACTION(point_value) {
    st.file.points.back().at = st.pop();
}

// ---------------------------------------------------------------- load blocks

YAMSC_ACTION(kw_load) {
    st.file.loads.emplace_back().loc = st.loc(in.position());
}
YAMSC_ACTION(load_kind) {
    st.file.loads.back().kind = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(load_name) {
    st.file.loads.back().id = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(load_open) {
    st.property_sinks.push_back(&st.file.loads.back().roles);
}
YAMSC_ACTION(load_close) {
    st.property_sinks.pop_back();
    st.file.loads.back().end = st.loc(in.position());
}

// ---------------------------------------------------------------- constraints

YAMSC_ACTION(kw_constraint) {
    st.file.constraints.emplace_back().loc = st.loc(in.position());
}
YAMSC_ACTION(constraint_kind) {
    st.file.constraints.back().kind = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(constraint_name) {
    st.file.constraints.back().id = ast::Named{in.string(), st.loc(in.position()), {}};
}
YAMSC_ACTION(constraint_open) {
    st.property_sinks.push_back(&st.file.constraints.back().roles);
}
YAMSC_ACTION(constraint_close) {
    st.property_sinks.pop_back();
    st.file.constraints.back().end = st.loc(in.position());
}

#undef YAMSC_ACTION
#undef YAMSC_CONTEXT_ACTION

} // namespace yamsc::parse
