#pragma once
// The grammar of the Standard Input Data (SID) text format (docs/sid-format.md) as PEGTL rule
// types. A SID file is read line by line: this grammar splits the text into lines of five
// shapes, and the rest of formats/sid/ assembles the nested blocks and checks what they mean:
//
//     name                    a block opens:        `refmod`, `origin`, `Me`
//     name = value            a key:                `nrow = 3`, `rframe = body ref`
//     name(i, j, ...) = value an indexed entry:     `m0( 1, 2) = 0.5`, `ielastq(1) = Mode 1`
//     new name [= value]      a numbered block:     `new modal`, `new node = 3`
//     end name                a block closes:       `end origin`
//
// Decisions (documented in docs/sid-format.md):
// - Everything before the first line that holds just `part` is a free-text header (tools write
//   titles and counts there); everything after `end part` is ignored with a warning.
// - Names are ASCII identifiers; the reader compares them case-insensitively.
// - A value is the rest of its line without surrounding blanks. It is a number when the whole
//   value is one: `12`, `-1.5`, `.5`, `2.`, `1e-3`, Fortran's `1.0D+03`, `nan`, `inf`.
// - Blanks are spaces, tabs, form feeds and CRs, so CR LF line ends read like LF ones.
// - A line whose first non-blank character is `#` or `!` is a comment.
// - Inside `part`, a line that fits none of the shapes is a syntax error; the reader reports it
//   and goes on with the next line.
#include <tao/pegtl.hpp>

namespace yamsc::sid::grammar {

namespace p = tao::pegtl;

// ---------------------------------------------------------------- lexical elements

struct blank : p::one<' ', '\t', '\f', '\v', '\r'> {};
struct blanks : p::star<blank> {};
struct line_end : p::sor<p::one<'\n'>, p::eof> {};
struct rest_of_line : p::star<p::not_one<'\n'>> {};
struct byte_order_mark : p::string<'\xEF', '\xBB', '\xBF'> {};

/// A case-insensitive keyword that is not the start of a longer name.
template <char... Cs> struct keyword : p::seq<p::istring<Cs...>, p::not_at<p::identifier_other>> {};
struct kw_part : keyword<'p', 'a', 'r', 't'> {};
struct kw_new : keyword<'n', 'e', 'w'> {};
struct kw_end : keyword<'e', 'n', 'd'> {};

// ---------------------------------------------------------------- numbers

struct sign : p::one<'+', '-'> {};
struct digits : p::plus<p::digit> {};
struct integer_literal : p::seq<p::opt<sign>, digits> {};
struct mantissa
    : p::sor<p::seq<digits, p::opt<p::one<'.'>, p::star<p::digit>>>, p::seq<p::one<'.'>, digits>> {
};
/// `e` as in C, `d` as Fortran writes double precision.
struct exponent : p::seq<p::one<'e', 'E', 'd', 'D'>, p::opt<sign>, digits> {};
/// Spelled out so that the reader can call them non-finite instead of "not a number".
struct non_finite : p::sor<keyword<'i', 'n', 'f', 'i', 'n', 'i', 't', 'y'>, keyword<'i', 'n', 'f'>,
                           keyword<'n', 'a', 'n'>> {};
struct real_literal : p::seq<p::opt<sign>, p::sor<p::seq<mantissa, p::opt<exponent>>, non_finite>> {
};

// ---------------------------------------------------------------- values

/// A value is the rest of the line; it is a number only when the number is all it holds.
struct integer_value : p::seq<integer_literal, blanks, p::at<line_end>> {};
struct real_value : p::seq<real_literal, blanks, p::at<line_end>> {};
struct text_value : rest_of_line {};
struct value : p::sor<integer_value, real_value, text_value> {};

// ---------------------------------------------------------------- lines

struct empty_line : line_end {};
struct comment_line : p::seq<p::one<'#', '!'>, rest_of_line, line_end> {};

struct end_name : p::identifier {};
struct end_line : p::seq<kw_end, blanks, p::must<end_name>, blanks, p::must<line_end>> {};

struct new_name : p::identifier {};
struct new_value : p::seq<p::one<'='>, blanks, value> {};
struct new_line
    : p::seq<kw_new, blanks, p::must<new_name>, blanks, p::opt<new_value>, p::must<line_end>> {};

struct key : p::identifier {};
struct index_number : integer_literal {};
struct index_close : p::one<')'> {};
struct equals : p::one<'='> {};
struct index_list
    : p::seq<p::one<'('>, blanks, p::must<index_number>, blanks,
             p::star<p::one<','>, blanks, p::must<index_number>, blanks>, p::must<index_close>> {};
struct block_rest : p::at<line_end> {};
struct assign_rest : p::seq<equals, blanks, value> {};
struct indexed_rest : p::seq<index_list, blanks, p::must<equals>, blanks, value> {};
/// What may follow a name: nothing, `= value` or `(indices) = value`.
struct key_rest : p::sor<block_rest, assign_rest, indexed_rest> {};
struct keyed_line : p::seq<key, blanks, p::must<key_rest>, p::must<line_end>> {};

/// Raised when a line starts with something that is not a name.
struct line_start {};
struct line : p::seq<blanks, p::sor<empty_line, comment_line, end_line, new_line, keyed_line,
                                    p::raise<line_start>>> {};
/// One line of the body of `part`; the reader recovers from an error at the next line.
struct body_line : p::seq<line> {};

// ---------------------------------------------------------------- the file

struct part_line : p::seq<blanks, kw_part, blanks, line_end> {};
struct end_part_line : p::seq<blanks, kw_end, blanks, kw_part, blanks, line_end> {};
struct header_line
    : p::seq<p::not_at<part_line>, p::not_at<p::eof>, rest_of_line, p::opt<p::one<'\n'>>> {};
struct header : p::star<header_line> {};
struct trailer : p::star<p::any> {};
struct body : p::seq<p::star<p::not_at<end_part_line>, p::not_at<p::eof>, body_line>,
                     p::opt<end_part_line, trailer>> {};
struct file : p::seq<p::opt<byte_order_mark>, header, p::opt<part_line, body>, p::eof> {};

} // namespace yamsc::sid::grammar
