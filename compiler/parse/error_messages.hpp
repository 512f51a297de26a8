#pragma once
// The error message of every rule the grammar requires with `must<>` (or `raise<>`), keyed by
// the rule. A rule without an entry does not compile. Templates may contain `{found}` (what
// the parser saw instead) and `{open}` (line:col of the innermost open bracket or block).
#include "grammar/model_grammar.hpp"
#include "parse/parse_state.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>

namespace yamsc::parse {

/// A composed message, with how many bytes past the error position it should point (to point
/// after a name, on the same line) and whether parsing resumes right at the error.
struct ErrorMessage {
    std::string text;
    std::size_t advance = 0;
    bool resume_here = false;
};

/// What the parser found at `rest` (the unparsed input), e.g. `'foo'`, `end of line`.
std::string describe_found(std::string_view rest);
/// Replaces `{found}` and `{open}` in a message template.
std::string fill_message(std::string_view text, std::string_view rest, const ParseState& st);

template <class Rule, class = void>
struct error_message; // deliberately undefined: every required rule needs a message

/// Every whole-expression rule shares one message.
template <class Rule>
struct error_message<Rule, std::enable_if_t<std::is_base_of_v<grammar::expression_marker, Rule>>> {
    static constexpr const char* text = "expected an expression, found {found}";
};

/// The operand after a binary or unary operator.
constexpr const char* operand_message = "expected an expression after the operator, found {found}";
template <class C> struct error_message<grammar::product<C>> {
    static constexpr const char* text = operand_message;
};
template <class C> struct error_message<grammar::unary<C>> {
    static constexpr const char* text = operand_message;
};
template <class C> struct error_message<grammar::exponent<C>> {
    static constexpr const char* text = operand_message;
};

#define YAMSC_ERROR_MESSAGE(RULE, TEXT)                                                            \
    template <> struct error_message<grammar::RULE> { static constexpr const char* text = TEXT; }

/// The message of a block that is not closed: parsing resumes at the statement that follows.
#define YAMSC_UNCLOSED_BLOCK_MESSAGE(RULE, TEXT)                                                   \
    template <> struct error_message<grammar::RULE> {                                              \
        static constexpr const char* text = TEXT;                                                  \
        static constexpr bool resume_here = true;                                                  \
    }

/// A message composed from the input at the error (e.g. "did you mean").
#define YAMSC_COMPOSED_ERROR_MESSAGE(RULE)                                                         \
    template <> struct error_message<grammar::RULE> {                                              \
        static ErrorMessage compose(std::string_view rest, const ParseState& st);                  \
    }

// ---- lexical
YAMSC_ERROR_MESSAGE(number_end, "unexpected {found} directly after a number");
YAMSC_ERROR_MESSAGE(input_order, "expected a whole number after 'order', found {found}");
YAMSC_ERROR_MESSAGE(approx_order, "expected a whole number after 'order', found {found}");
YAMSC_COMPOSED_ERROR_MESSAGE(string_close); // unterminated, or an unknown escape
YAMSC_ERROR_MESSAGE(end_of_statement, "expected end of statement, found {found}");

// ---- expressions
YAMSC_ERROR_MESSAGE(no_more_primes, "too many primes: at most two (q'') are allowed");
YAMSC_ERROR_MESSAGE(call_close,
                    "expected ',' or ')' to close the call started at {open}, found {found}");
YAMSC_ERROR_MESSAGE(paren_close, "expected ',' or ')' to close the '(' at {open}, found {found}");
YAMSC_ERROR_MESSAGE(component_name, "expected x, y or z after '.', found {found}");
YAMSC_ERROR_MESSAGE(standalone_end, "expected the end of the expression, found {found}");

// ---- property values
YAMSC_ERROR_MESSAGE(value, "expected a value (an expression, a string or a table), found {found}");
YAMSC_ERROR_MESSAGE(table_entry, "expected 'station: value' in the table, found {found}");
YAMSC_ERROR_MESSAGE(table_colon, "expected ':' between the station and its value, found {found}");
YAMSC_ERROR_MESSAGE(table_close,
                    "expected ',' or ')' to close the table started at {open}, found {found}");
YAMSC_ERROR_MESSAGE(modes_equals, "expected '=' after 'modes', found {found}");
YAMSC_ERROR_MESSAGE(mode_list,
                    "expected '(' and a list of modes, e.g. (q1, _, q2) or (flap1 -> q1), found "
                    "{found}");
YAMSC_ERROR_MESSAGE(mode_entry, "expected a DOF name, '_' or 'mode -> dof', found {found}");
YAMSC_ERROR_MESSAGE(mode_entry_dof, "expected a DOF name after '->', found {found}");
YAMSC_ERROR_MESSAGE(mode_list_close,
                    "expected ',' or ')' to close the list of modes started at {open}, found "
                    "{found}");

// ---- declarations
YAMSC_ERROR_MESSAGE(model_name, "expected a model name after 'model', found {found}");
YAMSC_ERROR_MESSAGE(param_decl, "expected a parameter name, found {found}");
YAMSC_ERROR_MESSAGE(param_after_name, "expected '=' or ',' after parameter name, found {found}");
YAMSC_ERROR_MESSAGE(input_decl, "expected an input name, found {found}");
YAMSC_ERROR_MESSAGE(dof_name, "expected a DOF name, found {found}");

// ---- bodies
YAMSC_ERROR_MESSAGE(rigid_name, "expected a body name after 'rigid', found {found}");
YAMSC_ERROR_MESSAGE(rigid_block, "expected '{' after the body name, found {found}");
YAMSC_UNCLOSED_BLOCK_MESSAGE(rigid_close, "expected '}' to close the body block started at {open}");
YAMSC_COMPOSED_ERROR_MESSAGE(unknown_rigid_item);
YAMSC_ERROR_MESSAGE(flexible_name, "expected a body name after 'flexible', found {found}");
YAMSC_ERROR_MESSAGE(flexible_block, "expected '{' after the body name, found {found}");
YAMSC_UNCLOSED_BLOCK_MESSAGE(flexible_close,
                             "expected '}' to close the body block started at {open}");
YAMSC_COMPOSED_ERROR_MESSAGE(unknown_flexible_item);
YAMSC_ERROR_MESSAGE(modes_property, "expected 'modes = (...)' after 'symbolic', found {found}");
YAMSC_ERROR_MESSAGE(beam_block, "expected '{' to start the beam block, found {found}");
YAMSC_UNCLOSED_BLOCK_MESSAGE(beam_close, "expected '}' to close the beam block started at {open}");
YAMSC_COMPOSED_ERROR_MESSAGE(unknown_beam_item);
YAMSC_ERROR_MESSAGE(mode_shape_name, "expected a mode name after 'mode', found {found}");
YAMSC_ERROR_MESSAGE(mode_direction,
                    "expected the direction x, y or z after the mode name, found {found}");
YAMSC_ERROR_MESSAGE(mode_shape_equals, "expected '=' after the mode direction, found {found}");

// ---- joints
YAMSC_ERROR_MESSAGE(joint_parent,
                    "expected the parent: ground, a body, body.tip or body.node(k), found {found}");
YAMSC_ERROR_MESSAGE(parent_point, "expected 'tip' or 'node(k)' after '.', found {found}");
YAMSC_ERROR_MESSAGE(node_open, "expected '(' after 'node', found {found}");
YAMSC_ERROR_MESSAGE(node_close, "expected ')' after the node number, found {found}");
YAMSC_ERROR_MESSAGE(joint_arrow,
                    "expected '->' between the parent and the child body, found {found}");
YAMSC_ERROR_MESSAGE(joint_child, "expected the child body name after '->', found {found}");
YAMSC_ERROR_MESSAGE(joint_tail,
                    "expected '{' or end of statement after the child body, found {found}");
YAMSC_ERROR_MESSAGE(axis,
                    "expected an axis: x, y, z, -x, -y, -z or a vector (a, b, c), found {found}");
YAMSC_ERROR_MESSAGE(free_list, "expected '(' and six DOF names after 'free', found {found}");
YAMSC_ERROR_MESSAGE(free_name, "expected a DOF name or '_', found {found}");
YAMSC_ERROR_MESSAGE(free_list_close,
                    "expected ',' or ')' to close the list started at {open}, found {found}");
YAMSC_UNCLOSED_BLOCK_MESSAGE(joint_close,
                             "expected '}' to close the joint block started at {open}");
YAMSC_COMPOSED_ERROR_MESSAGE(unknown_joint_item);

// ---- loads
YAMSC_ERROR_MESSAGE(force_on, "expected 'on' after 'force', found {found}");
YAMSC_ERROR_MESSAGE(force_body, "expected a body name after 'on', found {found}");
YAMSC_ERROR_MESSAGE(force_frame, "expected a frame (a body or ground) after 'in', found {found}");
YAMSC_ERROR_MESSAGE(force_equals,
                    "expected 'at', 'in' or '=' in the force statement, found {found}");
YAMSC_ERROR_MESSAGE(torque_on, "expected 'on' after 'torque', found {found}");
YAMSC_ERROR_MESSAGE(torque_body, "expected a body name after 'on', found {found}");
YAMSC_ERROR_MESSAGE(torque_frame, "expected a frame (a body or ground) after 'in', found {found}");
YAMSC_ERROR_MESSAGE(torque_equals, "expected 'in' or '=' in the torque statement, found {found}");
YAMSC_ERROR_MESSAGE(spring_dof, "expected a DOF name after 'spring', found {found}");
YAMSC_ERROR_MESSAGE(spring_terms,
                    "expected 'stiffness' or 'damping' after the DOF name, found {found}");
YAMSC_ERROR_MESSAGE(genforce_dof, "expected a DOF name after 'genforce', found {found}");
YAMSC_ERROR_MESSAGE(genforce_equals, "expected '=' after the DOF name, found {found}");

YAMSC_ERROR_MESSAGE(
    ext_target, "expected 'force on', 'torque on' or 'genforce' after 'external', found {found}");
YAMSC_ERROR_MESSAGE(ext_on, "expected 'on' after 'force' or 'torque', found {found}");
YAMSC_ERROR_MESSAGE(ext_body, "expected a body name after 'on', found {found}");
YAMSC_ERROR_MESSAGE(ext_frame, "expected a frame (a body or ground) after 'in', found {found}");
YAMSC_ERROR_MESSAGE(ext_dofs, "expected a DOF name or a list of DOFs (q1, q2), found {found}");
YAMSC_ERROR_MESSAGE(ext_dof, "expected a DOF name, found {found}");
YAMSC_ERROR_MESSAGE(ext_dof_close, "expected ',' or ')' to close the list of DOFs, found {found}");
YAMSC_ERROR_MESSAGE(ext_equals,
                    "expected 'at', 'in' or '=' in the external statement, found {found}");
YAMSC_ERROR_MESSAGE(ext_call,
                    "expected the function's name and its arguments, name(a, b), found {found}");
YAMSC_ERROR_MESSAGE(ext_args_open,
                    "expected '(' and the arguments after the function's name, found {found}");
YAMSC_ERROR_MESSAGE(ext_arg, "expected an argument (an expression), found {found}");
YAMSC_ERROR_MESSAGE(ext_arg_frame, "expected a frame (a body or ground) after 'in', found {found}");
YAMSC_ERROR_MESSAGE(ext_args_close, "expected ',' or ')' to close the arguments, found {found}");
YAMSC_ERROR_MESSAGE(ext_jacobian_word, "expected 'jacobian' after 'without', found {found}");

// ---- analysis
YAMSC_ERROR_MESSAGE(approx_symbol, "expected a name to approximate, found {found}");
YAMSC_ERROR_MESSAGE(assignment_equals, "expected '=' after the name, found {found}");
YAMSC_COMPOSED_ERROR_MESSAGE(unknown_linearize_item);
YAMSC_ERROR_MESSAGE(linearize_block, "expected '{' after 'linearize', found {found}");
YAMSC_UNCLOSED_BLOCK_MESSAGE(linearize_close,
                             "expected '}' to close the linearize block started at {open}");
YAMSC_COMPOSED_ERROR_MESSAGE(unknown_initial_item);
YAMSC_ERROR_MESSAGE(initial_block, "expected '{' after 'initial', found {found}");
YAMSC_UNCLOSED_BLOCK_MESSAGE(initial_close,
                             "expected '}' to close the initial block started at {open}");
YAMSC_ERROR_MESSAGE(output_name, "expected an output name, found {found}");
YAMSC_ERROR_MESSAGE(output_equals, "expected '=' after the output name, found {found}");
YAMSC_ERROR_MESSAGE(output_frame_section,
                    "expected `tip` or `node(k)` after the frame's '.', found {found}");
YAMSC_ERROR_MESSAGE(output_frame, "expected a frame (a body or ground) after 'in', found {found}");
YAMSC_ERROR_MESSAGE(point_name, "expected a point name, found {found}");
YAMSC_ERROR_MESSAGE(point_on, "expected 'on' after the point name, found {found}");
YAMSC_ERROR_MESSAGE(point_body, "expected a body name after 'on', found {found}");
YAMSC_ERROR_MESSAGE(point_at, "expected 'at' after the body name, found {found}");

// ---- statements
YAMSC_COMPOSED_ERROR_MESSAGE(unknown_statement);

// ---- load blocks
YAMSC_ERROR_MESSAGE(load_kind, "expected the kind of load block after 'load', found {found}");
YAMSC_ERROR_MESSAGE(load_name, "expected a name for the load block after its kind, found {found}");
YAMSC_ERROR_MESSAGE(load_block, "expected '{' after the load block's name, found {found}");
YAMSC_UNCLOSED_BLOCK_MESSAGE(load_close, "expected '}' to close the load block started at {open}");
YAMSC_COMPOSED_ERROR_MESSAGE(unknown_load_item);
YAMSC_ERROR_MESSAGE(constraint_kind,
                    "expected the kind of constraint after 'constraint', found {found}");
YAMSC_ERROR_MESSAGE(constraint_name,
                    "expected a name for the constraint after its kind, found {found}");
YAMSC_ERROR_MESSAGE(constraint_block, "expected '{' after the constraint's name, found {found}");
YAMSC_UNCLOSED_BLOCK_MESSAGE(constraint_close,
                             "expected '}' to close the constraint started at {open}");
YAMSC_COMPOSED_ERROR_MESSAGE(unknown_constraint_item);

#undef YAMSC_ERROR_MESSAGE
#undef YAMSC_UNCLOSED_BLOCK_MESSAGE
#undef YAMSC_COMPOSED_ERROR_MESSAGE

namespace detail {
template <class M, class = void> struct is_composed : std::false_type {};
template <class M> struct is_composed<M, std::void_t<decltype(&M::compose)>> : std::true_type {};
template <class M, class = void> struct resumes : std::false_type {};
template <class M>
struct resumes<M, std::void_t<decltype(M::resume_here)>> : std::bool_constant<M::resume_here> {};
} // namespace detail

/// The message for `Rule` failing with `rest` left to parse.
template <class Rule> ErrorMessage make_error_message(std::string_view rest, const ParseState& st) {
    using M = error_message<Rule>;
    if constexpr (detail::is_composed<M>::value) {
        return M::compose(rest, st);
    } else {
        return ErrorMessage{fill_message(M::text, rest, st), 0, detail::resumes<M>::value};
    }
}

} // namespace yamsc::parse
