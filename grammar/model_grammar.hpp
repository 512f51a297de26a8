#pragma once
// The grammar of the model language (`.mbd`, see docs/language.md) as PEGTL rule types.
// Types only: the actions that build the AST, the error messages (keyed by the rule given to
// `must<>`) and the error recovery live in compiler/parse/.
//
// Decisions the language reference leaves to the grammar (summarised in docs/language.md):
// - Numbers are unsigned literals: `12`, `1.5`, `.5`, `5.`, `2.5e-3`, `1E+4`. A leading minus is
//   unary negation, so `-2^2` is -(2^2) like `-x^2`. The literal text is kept exactly (`1e99999`
//   too); the checker decides what it means. A number may be followed directly by `deg` (`5deg`)
//   but not by another letter or digit (`2x` is an error).
// - Precedence, loosest first: `+ -` (left), `* /` (left), unary `-` `+`, `deg` (postfix on a
//   power: `x^2 deg` is (x^2) deg), `^` (right; its exponent may carry unary minus: `x^-2`),
//   postfix `.x/.y/.z`, then atoms. `5 deg` binds like a unit: `2*5 deg` is 2*(5 deg).
// - A call is a name followed by `(` (blanks allowed between them, except in mode shapes).
//   `(a)` is just `a`; `(a, b, ...)` with two or more elements is a vector.
// - Unary `+` is accepted and dropped.
// - Inside parentheses, lists and tables, line breaks and comments may separate tokens; anywhere
//   else a statement ends at a newline, `;`, a `}` closing its block, or the end of the file.
//   Line breaks are LF or CR LF; a UTF-8 byte order mark at the start is skipped.
// - Juxtaposition multiplies only in mode shapes: `mode fa1 x = 0.7 z^2 - 5 z^3`.
// - Strings are on one line; the escapes are `\"` and `\\` only.
// - A block's `{` is on the line of its statement; its items end like statements.
// - `input a order 2, b`: `order` applies to the name it follows. `approx a, b order 2`: to the
//   group; without `order` the order is 1.
// - `spring q stiffness K damping D`: either term or both, in either order.
// - `free (...)` lists DOF names or `_`; the parser requires six of them.
#include <tao/pegtl.hpp>

#include <type_traits>

namespace yamsc::grammar {

namespace p = tao::pegtl;

// ---------------------------------------------------------------- lexical elements

struct blank : p::one<' ', '\t', '\f', '\v'> {};
struct blanks : p::star<blank> {};
/// LF or CR LF (a lone CR is not a line break: it is reported where it stands).
struct newline : p::sor<p::one<'\n'>, p::string<'\r', '\n'>> {};
struct comment : p::seq<p::one<'#'>, p::star<p::not_one<'\n'>>> {};
/// Between the tokens of a bracketed list: blanks, line breaks and comments.
struct gap : p::star<p::sor<blank, newline, comment>> {};

struct identifier : p::identifier {};

struct kw_model : TAO_PEGTL_KEYWORD("model") {};
struct kw_param : TAO_PEGTL_KEYWORD("param") {};
struct kw_input : TAO_PEGTL_KEYWORD("input") {};
struct kw_dof : TAO_PEGTL_KEYWORD("dof") {};
struct kw_gravity : TAO_PEGTL_KEYWORD("gravity") {};
struct kw_rigid : TAO_PEGTL_KEYWORD("rigid") {};
struct kw_flexible : TAO_PEGTL_KEYWORD("flexible") {};
struct kw_joint : TAO_PEGTL_KEYWORD("joint") {};
struct kw_force : TAO_PEGTL_KEYWORD("force") {};
struct kw_torque : TAO_PEGTL_KEYWORD("torque") {};
struct kw_spring : TAO_PEGTL_KEYWORD("spring") {};
struct kw_genforce : TAO_PEGTL_KEYWORD("genforce") {};
struct kw_approx : TAO_PEGTL_KEYWORD("approx") {};
struct kw_linearize : TAO_PEGTL_KEYWORD("linearize") {};
struct kw_initial : TAO_PEGTL_KEYWORD("initial") {};
struct kw_output : TAO_PEGTL_KEYWORD("output") {};
struct kw_point : TAO_PEGTL_KEYWORD("point") {};
struct kw_external : TAO_PEGTL_KEYWORD("external") {};
struct kw_load : TAO_PEGTL_KEYWORD("load") {};
struct kw_constraint : TAO_PEGTL_KEYWORD("constraint") {};

struct kw_order : TAO_PEGTL_KEYWORD("order") {};
struct kw_deg : TAO_PEGTL_KEYWORD("deg") {};
struct kw_beam : TAO_PEGTL_KEYWORD("beam") {};
struct kw_symbolic : TAO_PEGTL_KEYWORD("symbolic") {};
struct kw_modes : TAO_PEGTL_KEYWORD("modes") {};
struct kw_mode : TAO_PEGTL_KEYWORD("mode") {};
struct kw_tip : TAO_PEGTL_KEYWORD("tip") {};
struct kw_node : TAO_PEGTL_KEYWORD("node") {};
struct kw_at : TAO_PEGTL_KEYWORD("at") {};
struct kw_translate : TAO_PEGTL_KEYWORD("translate") {};
struct kw_rotate : TAO_PEGTL_KEYWORD("rotate") {};
struct kw_free : TAO_PEGTL_KEYWORD("free") {};
struct kw_on : TAO_PEGTL_KEYWORD("on") {};
struct kw_in : TAO_PEGTL_KEYWORD("in") {};
struct kw_stiffness : TAO_PEGTL_KEYWORD("stiffness") {};
struct kw_damping : TAO_PEGTL_KEYWORD("damping") {};

/// The words that start a top-level statement. A block that meets one of them was not closed.
struct statement_keyword
    : p::sor<kw_model, kw_param, kw_input, kw_dof, kw_gravity, kw_rigid, kw_flexible, kw_joint,
             kw_force, kw_torque, kw_spring, kw_genforce, kw_approx, kw_linearize, kw_initial,
             kw_output, kw_point, kw_external, kw_load, kw_constraint> {};

struct digits : p::plus<p::digit> {};
struct mantissa
    : p::sor<p::seq<digits, p::opt<p::one<'.'>, p::star<p::digit>>>, p::seq<p::one<'.'>, digits>> {
};
struct exponent_part : p::seq<p::one<'e', 'E'>, p::opt<p::one<'+', '-'>>, digits> {};
struct number : p::seq<mantissa, p::opt<exponent_part>> {};
/// What may follow a number: anything but a letter, digit or `_`, except the `deg` suffix.
struct number_end : p::sor<p::at<kw_deg>, p::not_at<p::identifier_other>> {};
struct number_literal : p::seq<number, p::must<number_end>> {};

/// A non-negative integer such as an `order`: no fraction, exponent or trailing letters.
struct integer : p::seq<digits, p::not_at<p::one<'.', 'e', 'E'>>, p::not_at<p::identifier_other>> {
};

struct escape : p::seq<p::one<'\\'>, p::one<'"', '\\'>> {};
struct string_body : p::star<p::sor<escape, p::not_one<'"', '\\', '\n'>>> {};
struct string_close : p::one<'"'> {};
struct string_literal : p::seq<p::one<'"'>, string_body, p::must<string_close>> {};

/// Where a statement may end (looking ahead only).
struct statement_end_ahead : p::seq<blanks, p::sor<p::one<'#', ';', '}'>, newline, p::eof>> {};
struct trailing_comment : comment {};
struct end_of_statement : p::seq<blanks, p::opt<trailing_comment>,
                                 p::sor<newline, p::one<';'>, p::at<p::one<'}'>>, p::eof>> {};

// ---------------------------------------------------------------- expressions

/// How an expression continues: `sep` separates its tokens, `inner` is the context inside
/// parentheses, `call_gap` may stand between a function name and `(`, and `juxtapose` says
/// whether `0.7 z^2` multiplies (mode shapes only).
template <bool Multiline, bool Juxtapose> struct expression_context {
    using sep = std::conditional_t<Multiline, gap, blanks>;
    using inner = expression_context<true, Juxtapose>;
    using call_gap = std::conditional_t<Juxtapose, p::success, blanks>;
    static constexpr bool juxtapose = Juxtapose;
};
using line_context = expression_context<false, false>;
using bracket_context = expression_context<true, false>;
using shape_context = expression_context<false, true>;

/// Base of every rule that is a whole expression (one error message for all of them).
struct expression_marker {};

template <class C> struct expression;
template <class C> struct unary;
template <class C> struct exponent;
template <class C> struct degree;

struct expr_name : identifier {};
struct expr_primes : p::rep_opt<2, p::one<'\''>> {};
struct no_more_primes : p::not_at<p::one<'\''>> {};

struct call_open : p::one<'('> {};
struct call_close : p::one<')'> {};
template <class C>
struct call_paren
    : p::seq<call_open, gap,
             p::opt<expression<typename C::inner>, gap,
                    p::star<p::one<','>, gap, p::must<expression<typename C::inner>>, gap>>,
             p::must<call_close>> {};
template <class C> struct call_args : p::seq<typename C::call_gap, call_paren<C>> {};

template <class C>
struct name_or_call
    : p::seq<expr_name, p::sor<call_args<C>, p::seq<expr_primes, p::must<no_more_primes>>>> {};

struct paren_open : p::one<'('> {};
struct paren_close : p::one<')'> {};
template <class C>
struct paren_group : p::seq<paren_open, gap, p::must<expression<typename C::inner>>, gap,
                            p::star<p::one<','>, gap, p::must<expression<typename C::inner>>, gap>,
                            p::must<paren_close>> {};

template <class C> struct primary : p::sor<number_literal, name_or_call<C>, paren_group<C>> {};

struct component_name : p::seq<p::one<'x', 'y', 'z'>, p::not_at<p::identifier_other>> {};
struct component : p::seq<p::one<'.'>, p::must<component_name>> {};
// `tower.tip`, `tower.node(10)`: a section of a flexible body, for the reaction
// loads through it (`reaction_moment(tower.node(10))`; the checker allows it there only).
struct node_open : p::one<'('> {};
struct node_close : p::one<')'> {};
struct section_tip : kw_tip {};
template <class C>
struct section_node : p::seq<kw_node, blanks, p::must<node_open>, gap,
                             p::must<expression<typename C::inner>>, gap, p::must<node_close>> {};
template <class C> struct section : p::seq<p::one<'.'>, p::sor<section_tip, section_node<C>>> {};
template <class C> struct postfix : p::seq<primary<C>, p::star<p::sor<section<C>, component>>> {};

template <class C> struct pow_op : p::seq<p::one<'^'>, typename C::sep, p::must<exponent<C>>> {};
template <class C> struct power : p::seq<postfix<C>, p::opt<typename C::sep, pow_op<C>>> {};
template <class C>
struct exponent_neg : p::seq<p::one<'-'>, typename C::sep, p::must<exponent<C>>> {};
template <class C> struct exponent : p::sor<exponent_neg<C>, power<C>> {};

struct deg_op : kw_deg {};
template <class C> struct degree : p::seq<power<C>, p::opt<typename C::sep, deg_op>> {};

template <class C> struct negation : p::seq<p::one<'-'>, typename C::sep, p::must<unary<C>>> {};
template <class C> struct unary_plus : p::seq<p::one<'+'>, typename C::sep, p::must<unary<C>>> {};
template <class C> struct unary : p::sor<negation<C>, unary_plus<C>, degree<C>> {};

struct juxtaposition_start : p::sor<p::identifier_first, p::one<'('>> {};
template <class C>
struct juxtaposed
    : std::conditional_t<C::juxtapose, p::seq<p::at<juxtaposition_start>, degree<C>>, p::failure> {
};
template <class C> struct mul_op : p::seq<p::one<'*'>, typename C::sep, p::must<unary<C>>> {};
template <class C> struct div_op : p::seq<p::one<'/'>, typename C::sep, p::must<unary<C>>> {};
template <class C>
struct product
    : p::seq<unary<C>, p::star<typename C::sep, p::sor<mul_op<C>, div_op<C>, juxtaposed<C>>>> {};

template <class C> struct add_op : p::seq<p::one<'+'>, typename C::sep, p::must<product<C>>> {};
template <class C> struct sub_op : p::seq<p::one<'-'>, typename C::sep, p::must<product<C>>> {};
template <class C>
struct sum : p::seq<product<C>, p::star<typename C::sep, p::sor<add_op<C>, sub_op<C>>>> {};

template <class C> struct expression : sum<C>, expression_marker {};

/// An expression on one line (unless bracketed): the right-hand side of most statements.
struct line_expression : expression<line_context> {};

// ---------------------------------------------------------------- block structure

/// Marks a rule whose failure to parse is reported and skipped, so parsing continues.
/// InBlock: a `}` ends the skipped text (it closes the enclosing block).
template <class Rule, bool InBlock> struct recoverable : p::seq<Rule> {};

struct item_separator : p::sor<blank, newline, comment, p::one<';'>> {};
/// A `}`, the end, or a statement's keyword (the block was not closed), unless the keyword is
/// the name of a property (`joint = revolute` in a constraint).
struct block_stop
    : p::sor<p::one<'}'>, p::eof, p::seq<statement_keyword, p::not_at<blanks, p::one<'='>>>> {};
template <class Item> struct item_line : p::seq<Item, p::must<end_of_statement>> {};
template <class Item>
struct block_items : p::seq<p::star<item_separator>,
                            p::star<p::not_at<block_stop>, recoverable<item_line<Item>, true>,
                                    p::star<item_separator>>> {};

// ---------------------------------------------------------------- property values

struct value_string : string_literal {};

struct table_open : p::one<'('> {};
struct table_station : expression<bracket_context> {};
struct table_colon : p::one<':'> {};
struct table_point_value : expression<bracket_context> {};
struct table_entry
    : p::seq<table_station, gap, p::must<table_colon>, gap, p::must<table_point_value>> {};
struct table_close : p::one<')'> {};
struct table : p::seq<table_open, gap, p::must<table_entry>, gap,
                      p::star<p::one<','>, gap, p::must<table_entry>, gap>, p::must<table_close>> {
};
struct table_start : p::seq<p::one<'('>, gap, expression<bracket_context>, gap, p::one<':'>> {};
struct value_table : p::seq<p::at<table_start>, table> {};

struct value_expression : line_expression {};
struct value : p::sor<value_string, value_table, value_expression> {};

struct property_key : identifier {};
struct property_start : p::seq<identifier, blanks, p::one<'='>> {};
struct property
    : p::seq<p::at<property_start>, property_key, blanks, p::one<'='>, blanks, p::must<value>> {};

struct mode_list_open : p::one<'('> {};
struct mode_entry_name : identifier {};
struct mode_entry_dof : identifier {};
struct mode_arrow : p::seq<p::string<'-', '>'>, gap, p::must<mode_entry_dof>> {};
struct mode_entry : p::seq<mode_entry_name, p::opt<gap, mode_arrow>> {};
struct mode_list_close : p::one<')'> {};
struct mode_list
    : p::seq<mode_list_open, gap, p::must<mode_entry>, gap,
             p::star<p::one<','>, gap, p::must<mode_entry>, gap>, p::must<mode_list_close>> {};
struct modes_equals : p::one<'='> {};
struct modes_property
    : p::seq<kw_modes, blanks, p::must<modes_equals>, blanks, p::must<mode_list>> {};

// ---------------------------------------------------------------- declarations

struct model_name : identifier {};
struct model_title : string_literal {};
struct model_statement
    : p::seq<kw_model, blanks, p::must<model_name>, blanks, p::opt<model_title>> {};

struct param_name : identifier {};
struct param_value : line_expression {};
struct param_default : p::seq<p::one<'='>, blanks, p::must<param_value>> {};
struct param_after_name : p::sor<param_default, p::at<p::one<','>>, p::at<statement_end_ahead>> {};
struct param_decl : p::seq<param_name, blanks, p::must<param_after_name>> {};
struct param_statement : p::seq<kw_param, blanks, p::must<param_decl>,
                                p::star<blanks, p::one<','>, blanks, p::must<param_decl>>> {};

struct input_name : identifier {};
struct input_order : integer {};
struct input_decl : p::seq<input_name, p::opt<blanks, kw_order, blanks, p::must<input_order>>> {};
struct input_statement : p::seq<kw_input, blanks, p::must<input_decl>,
                                p::star<blanks, p::one<','>, blanks, p::must<input_decl>>> {};

struct dof_name : identifier {};
struct dof_statement : p::seq<kw_dof, blanks, p::must<dof_name>,
                              p::star<blanks, p::one<','>, blanks, p::must<dof_name>>> {};

struct gravity_value : line_expression {};
struct gravity_statement : p::seq<kw_gravity, blanks, p::must<gravity_value>> {};

// ---------------------------------------------------------------- bodies

struct rigid_name : identifier {};
struct rigid_open : p::one<'{'> {};
struct rigid_close : p::one<'}'> {};
struct unknown_rigid_item {};
struct rigid_item : p::sor<property, p::raise<unknown_rigid_item>> {};
struct rigid_block : p::seq<rigid_open, block_items<rigid_item>, p::must<rigid_close>> {};
struct rigid_statement
    : p::seq<kw_rigid, blanks, p::must<rigid_name>, blanks, p::must<rigid_block>> {};

struct mode_shape_name : identifier {};
struct mode_direction : p::seq<p::one<'x', 'y', 'z'>, p::not_at<p::identifier_other>> {};
struct mode_shape_equals : p::one<'='> {};
struct mode_shape_value : expression<shape_context> {};
struct mode_shape
    : p::seq<kw_mode, blanks, p::must<mode_shape_name>, blanks, p::must<mode_direction>, blanks,
             p::must<mode_shape_equals>, blanks, p::must<mode_shape_value>> {};

struct beam_file : string_literal {};
struct beam_format : identifier {};
struct beam_open : p::one<'{'> {};
struct beam_close : p::one<'}'> {};
struct unknown_beam_item {};
struct beam_item : p::sor<mode_shape, modes_property, property, p::raise<unknown_beam_item>> {};
struct beam_block : p::seq<beam_open, block_items<beam_item>, p::must<beam_close>> {};
struct beam : p::seq<kw_beam, blanks, p::opt<beam_file, blanks>, p::opt<beam_format, blanks>,
                     p::must<beam_block>> {};

struct symbolic_modes : p::seq<kw_symbolic, blanks, p::must<modes_property>> {};

struct flexible_name : identifier {};
struct flexible_open : p::one<'{'> {};
struct flexible_close : p::one<'}'> {};
struct unknown_flexible_item {};
struct flexible_item
    : p::sor<beam, symbolic_modes, modes_property, property, p::raise<unknown_flexible_item>> {};
struct flexible_block : p::seq<flexible_open, block_items<flexible_item>, p::must<flexible_close>> {
};
struct flexible_statement
    : p::seq<kw_flexible, blanks, p::must<flexible_name>, blanks, p::must<flexible_block>> {};

// ---------------------------------------------------------------- joints

struct parent_body : identifier {};
struct parent_tip : kw_tip {};
struct node_number : expression<bracket_context> {};
struct parent_node : p::seq<kw_node, blanks, p::must<node_open>, gap, p::must<node_number>, gap,
                            p::must<node_close>> {};
struct parent_point : p::sor<parent_tip, parent_node> {};
struct joint_parent : p::seq<parent_body, p::opt<p::one<'.'>, p::must<parent_point>>> {};
struct joint_arrow : p::string<'-', '>'> {};
struct joint_child : identifier {};

struct at_value : line_expression {};
struct at_step : p::seq<kw_at, blanks, p::must<at_value>> {};

struct axis_name
    : p::seq<p::opt<p::one<'-'>>, p::one<'x', 'y', 'z'>, p::not_at<p::identifier_other>> {};
struct axis_vector : p::seq<paren_group<line_context>> {};
struct axis : p::sor<axis_name, axis_vector> {};
struct step_arg : line_expression {};
struct translate_step : p::seq<kw_translate, blanks, p::must<axis>, blanks, p::must<step_arg>> {};
struct rotate_step : p::seq<kw_rotate, blanks, p::must<axis>, blanks, p::must<step_arg>> {};

struct free_list_open : p::one<'('> {};
struct free_name : identifier {};
struct free_list_close : p::one<')'> {};
struct free_list
    : p::seq<free_list_open, gap, p::must<free_name>, gap,
             p::star<p::one<','>, gap, p::must<free_name>, gap>, p::must<free_list_close>> {};
struct free_step : p::seq<kw_free, blanks, p::must<free_list>> {};

struct joint_option : property {};
struct unknown_joint_item {};
struct joint_item : p::sor<at_step, translate_step, rotate_step, free_step, joint_option,
                           p::raise<unknown_joint_item>> {};
struct joint_open : p::one<'{'> {};
struct joint_close : p::one<'}'> {};
struct joint_block : p::seq<joint_open, block_items<joint_item>, p::must<joint_close>> {};
struct joint_tail : p::sor<joint_block, p::at<statement_end_ahead>> {};
struct joint_statement
    : p::seq<kw_joint, blanks, p::must<joint_parent>, blanks, p::must<joint_arrow>, blanks,
             p::must<joint_child>, blanks, p::must<joint_tail>> {};

// ---------------------------------------------------------------- loads

struct force_on : kw_on {};
struct force_body : identifier {};
struct force_at_value : line_expression {};
struct force_at : p::seq<kw_at, blanks, p::must<force_at_value>, blanks> {};
struct force_frame : identifier {};
struct force_in : p::seq<kw_in, blanks, p::must<force_frame>, blanks> {};
struct force_equals : p::one<'='> {};
struct force_value : line_expression {};
struct force_statement : p::seq<kw_force, blanks, p::must<force_on>, blanks, p::must<force_body>,
                                blanks, p::opt<force_at>, p::opt<force_in>, p::must<force_equals>,
                                blanks, p::must<force_value>> {};

struct torque_on : kw_on {};
struct torque_body : identifier {};
struct torque_frame : identifier {};
struct torque_in : p::seq<kw_in, blanks, p::must<torque_frame>, blanks> {};
struct torque_equals : p::one<'='> {};
struct torque_value : line_expression {};
struct torque_statement
    : p::seq<kw_torque, blanks, p::must<torque_on>, blanks, p::must<torque_body>, blanks,
             p::opt<torque_in>, p::must<torque_equals>, blanks, p::must<torque_value>> {};

struct spring_dof : identifier {};
struct stiffness_value : line_expression {};
struct damping_value : line_expression {};
struct stiffness_term : p::seq<kw_stiffness, blanks, p::must<stiffness_value>> {};
struct damping_term : p::seq<kw_damping, blanks, p::must<damping_value>> {};
struct spring_terms : p::sor<p::seq<stiffness_term, p::opt<blanks, damping_term>>,
                             p::seq<damping_term, p::opt<blanks, stiffness_term>>> {};
struct spring_statement
    : p::seq<kw_spring, blanks, p::must<spring_dof>, blanks, p::must<spring_terms>> {};

struct genforce_dof : identifier {};
struct genforce_equals : p::one<'='> {};
struct genforce_value : line_expression {};
struct genforce_statement : p::seq<kw_genforce, blanks, p::must<genforce_dof>, blanks,
                                   p::must<genforce_equals>, blanks, p::must<genforce_value>> {};

// ---------------------------------------------------------------- analysis

struct approx_symbol : identifier {};
struct approx_order : integer {};
struct approx_statement : p::seq<kw_approx, blanks, p::must<approx_symbol>,
                                 p::star<blanks, p::one<','>, blanks, p::must<approx_symbol>>,
                                 p::opt<blanks, kw_order, blanks, p::must<approx_order>>> {};

struct assignment_name : identifier {};
struct assignment_primes : p::rep_opt<2, p::one<'\''>> {};
struct assignment_equals : p::one<'='> {};
struct assignment_value : line_expression {};
struct assignment : p::seq<assignment_name, assignment_primes, p::must<no_more_primes>, blanks,
                           p::must<assignment_equals>, blanks, p::must<assignment_value>> {};
struct unknown_linearize_item {};
struct linearize_item : p::sor<assignment, p::raise<unknown_linearize_item>> {};
struct linearize_open : p::one<'{'> {};
struct linearize_close : p::one<'}'> {};
struct linearize_block
    : p::seq<linearize_open, block_items<linearize_item>, p::must<linearize_close>> {};
struct linearize_statement : p::seq<kw_linearize, blanks, p::must<linearize_block>> {};

/// Extension: `initial { q = 2; psi' = 1.05 }`, the default initial state of `yamsc sim`.
struct unknown_initial_item {};
struct initial_item : p::sor<assignment, p::raise<unknown_initial_item>> {};
struct initial_open : p::one<'{'> {};
struct initial_close : p::one<'}'> {};
struct initial_block : p::seq<initial_open, block_items<initial_item>, p::must<initial_close>> {};
struct initial_statement : p::seq<kw_initial, blanks, p::must<initial_block>> {};

struct output_name : identifier {};
struct output_equals : p::one<'='> {};
struct output_value : line_expression {};
struct output_frame : identifier {};
// `in tower.node(10)`, `in blade.tip`: the frame of a node of a flexible body (as a
// joint on it would start), for the loads through its section.
struct output_frame_tip : kw_tip {};
struct output_frame_node : expression<bracket_context> {};
struct output_frame_section
    : p::sor<output_frame_tip, p::seq<kw_node, blanks, p::must<node_open>, gap,
                                      p::must<output_frame_node>, gap, p::must<node_close>>> {};
struct output_in : p::seq<kw_in, blanks, p::must<output_frame>,
                          p::opt<p::one<'.'>, p::must<output_frame_section>>> {};
struct output_statement
    : p::seq<kw_output, blanks, p::must<output_name>, blanks, p::must<output_equals>, blanks,
             p::must<output_value>, p::opt<blanks, output_in>> {};

/// Extension: a named point fixed in a body, `point tip_pt on blade at (0, 0, L)`.
struct point_name : identifier {};
struct point_on : kw_on {};
struct point_body : identifier {};
struct point_at : kw_at {};
struct point_value : line_expression {};
struct point_statement
    : p::seq<kw_point, blanks, p::must<point_name>, blanks, p::must<point_on>, blanks,
             p::must<point_body>, blanks, p::must<point_at>, blanks, p::must<point_value>> {};

// ---------------------------------------------------------------- external functions

/// `external force on B at (..) in F = name(arg [in FRAME], ...) [without jacobian]`: a load
/// computed by a C function the user provides (docs/language.md). The target words are their
/// own rules so that the actions of `force`, `torque` and `genforce` statements stay apart.
struct ext_force_word : TAO_PEGTL_KEYWORD("force") {};
struct ext_torque_word : TAO_PEGTL_KEYWORD("torque") {};
struct ext_genforce_word : TAO_PEGTL_KEYWORD("genforce") {};
struct ext_on : kw_on {};
struct ext_body : identifier {};
struct ext_at_value : line_expression {};
struct ext_at : p::seq<kw_at, blanks, p::must<ext_at_value>, blanks> {};
struct ext_frame : identifier {};
struct ext_in : p::seq<kw_in, blanks, p::must<ext_frame>, blanks> {};
struct ext_force_target : p::seq<ext_force_word, blanks, p::must<ext_on>, blanks, p::must<ext_body>,
                                 blanks, p::opt<ext_at>, p::opt<ext_in>> {};
struct ext_torque_target : p::seq<ext_torque_word, blanks, p::must<ext_on>, blanks,
                                  p::must<ext_body>, blanks, p::opt<ext_in>> {};
struct ext_dof : identifier {};
struct ext_dof_close : p::one<')'> {};
struct ext_dof_list
    : p::seq<p::one<'('>, gap, p::must<ext_dof>, gap,
             p::star<p::one<','>, gap, p::must<ext_dof>, gap>, p::must<ext_dof_close>> {};
struct ext_dofs : p::sor<ext_dof_list, ext_dof> {};
struct ext_genforce_target : p::seq<ext_genforce_word, blanks, p::must<ext_dofs>, blanks> {};
struct ext_target : p::sor<ext_force_target, ext_torque_target, ext_genforce_target> {};
struct ext_equals : p::one<'='> {};
struct ext_function : identifier {};
struct ext_args_open : p::one<'('> {};
struct ext_arg_value : expression<bracket_context> {};
struct ext_arg_frame : identifier {};
struct ext_arg_in : p::seq<kw_in, blanks, p::must<ext_arg_frame>> {};
struct ext_arg : p::seq<ext_arg_value, p::opt<gap, ext_arg_in>> {};
struct ext_args_close : p::one<')'> {};
struct ext_call
    : p::seq<ext_function, blanks, p::must<ext_args_open>, gap, p::must<ext_arg>, gap,
             p::star<p::one<','>, gap, p::must<ext_arg>, gap>, p::must<ext_args_close>> {};
struct ext_jacobian_word : TAO_PEGTL_KEYWORD("jacobian") {};
struct ext_without : p::seq<TAO_PEGTL_KEYWORD("without"), blanks, p::must<ext_jacobian_word>> {};
struct external_statement : p::seq<kw_external, blanks, p::must<ext_target>, p::must<ext_equals>,
                                   blanks, p::must<ext_call>, p::opt<blanks, ext_without>> {};

// ---------------------------------------------------------------- load blocks

/// `load rotor_table aero { wind = V_wind; thrust = thrust; ... }`: a load block of the
/// runtime (docs/language.md, Load blocks) and what each of its roles is bound to: `role =
/// value`, a property, so that later kinds can take names of points or bodies, lists of them
/// and file names. The checker knows the kinds and their roles.
struct load_kind : identifier {};
struct load_name : identifier {};
struct load_open : p::one<'{'> {};
struct load_close : p::one<'}'> {};
struct unknown_load_item {};
struct load_item : p::sor<property, p::raise<unknown_load_item>> {};
struct load_block : p::seq<load_open, block_items<load_item>, p::must<load_close>> {};
struct load_statement : p::seq<kw_load, blanks, p::must<load_kind>, blanks, p::must<load_name>,
                               blanks, p::must<load_block>> {};

// ---------------------------------------------------------------- constraints

/// `constraint loop closing { a = crank.tip; b = rocker; joint = revolute; axis = z }`: rows
/// the coordinates must satisfy (docs/language.md, Constraints). The same shape as a load
/// block: a kind, a name and `role = value` properties; the checker knows the kinds
/// (model/constraint_kinds.cpp) and their roles.
struct constraint_kind : identifier {};
struct constraint_name : identifier {};
struct constraint_open : p::one<'{'> {};
struct constraint_close : p::one<'}'> {};
struct unknown_constraint_item {};
struct constraint_item : p::sor<property, p::raise<unknown_constraint_item>> {};
struct constraint_block
    : p::seq<constraint_open, block_items<constraint_item>, p::must<constraint_close>> {};
struct constraint_statement : p::seq<kw_constraint, blanks, p::must<constraint_kind>, blanks,
                                     p::must<constraint_name>, blanks, p::must<constraint_block>> {
};

// ---------------------------------------------------------------- the file

struct unknown_statement {};
struct statement : p::sor<model_statement, param_statement, input_statement, dof_statement,
                          gravity_statement, rigid_statement, flexible_statement, joint_statement,
                          force_statement, torque_statement, spring_statement, genforce_statement,
                          approx_statement, linearize_statement, initial_statement,
                          output_statement, point_statement, external_statement, load_statement,
                          constraint_statement, p::raise<unknown_statement>> {};
struct statement_line : p::seq<statement, p::must<end_of_statement>> {};
struct top_separator : p::plus<item_separator> {};
struct model_file
    : p::seq<p::opt<p::utf8::bom>,
             p::star<p::not_at<p::eof>, p::sor<top_separator, recoverable<statement_line, false>>>,
             p::eof> {};

/// A lone expression, e.g. the value of `--set theta_t=5deg` on the command line.
struct standalone_value : line_expression {};
struct standalone_end : p::eof {};
struct standalone_expression
    : p::seq<blanks, p::must<standalone_value>, blanks, p::must<standalone_end>> {};

} // namespace yamsc::grammar
