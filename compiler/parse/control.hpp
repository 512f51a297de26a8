#pragma once
// The PEGTL control class of the model parser: turns a failed `must<>` into a located error
// with the rule's message, keeps track of open brackets (for "to close the '(' at 3:5") and of
// the nesting depth (a Limit error instead of a stack overflow), and implements error recovery
// for the rules the grammar marks `recoverable`.
#include "grammar/model_grammar.hpp"
#include "parse/error_messages.hpp"
#include "parse/parse_state.hpp"
#include "parse/recovery.hpp"

#include <tao/pegtl.hpp>

#include <algorithm>
#include <string_view>
#include <type_traits>

namespace yamsc::parse {

/// Rules that open a bracket or block whose position an error message may quote.
template <class Rule> struct opens_bracket : std::false_type {};
template <class C> struct opens_bracket<grammar::paren_group<C>> : std::true_type {};
template <class C> struct opens_bracket<grammar::call_paren<C>> : std::true_type {};
template <> struct opens_bracket<grammar::table> : std::true_type {};
template <> struct opens_bracket<grammar::mode_list> : std::true_type {};
template <> struct opens_bracket<grammar::free_list> : std::true_type {};
template <> struct opens_bracket<grammar::rigid_block> : std::true_type {};
template <> struct opens_bracket<grammar::flexible_block> : std::true_type {};
template <> struct opens_bracket<grammar::beam_block> : std::true_type {};
template <> struct opens_bracket<grammar::joint_block> : std::true_type {};
template <> struct opens_bracket<grammar::linearize_block> : std::true_type {};
template <> struct opens_bracket<grammar::initial_block> : std::true_type {};
template <> struct opens_bracket<grammar::load_block> : std::true_type {};
template <> struct opens_bracket<grammar::constraint_block> : std::true_type {};

/// Rules that recurse into expressions: their depth is limited.
template <class Rule> struct nests : std::false_type {};
template <class C> struct nests<grammar::paren_group<C>> : std::true_type {};
template <class C> struct nests<grammar::call_paren<C>> : std::true_type {};
template <class C> struct nests<grammar::negation<C>> : std::true_type {};
template <class C> struct nests<grammar::unary_plus<C>> : std::true_type {};
template <class C> struct nests<grammar::exponent_neg<C>> : std::true_type {};
template <class C> struct nests<grammar::pow_op<C>> : std::true_type {};

template <class Rule> struct control : tao::pegtl::normal<Rule> {
    template <class Input> static void start(const Input& in, ParseState& st) {
        if constexpr (nests<Rule>::value) {
            if (st.nesting >= Limits::max_nesting) {
                throw syntax_error("expression is nested too deeply (more than " +
                                       std::to_string(Limits::max_nesting) +
                                       " levels of brackets, signs or powers)",
                                   in.position(), diag::Kind::Limit);
            }
            ++st.nesting;
        }
        if constexpr (opens_bracket<Rule>::value) st.open_brackets.push_back(st.loc(in.position()));
    }

    template <class Input> static void success(const Input&, ParseState& st) { leave(st); }

    template <class Input> static void failure(const Input&, ParseState& st) { leave(st); }

    template <class Input> [[noreturn]] static void raise(const Input& in, ParseState& st) {
        const std::string_view rest(in.current(), in.size());
        const ErrorMessage message = make_error_message<Rule>(rest, st);
        tao::pegtl::position where = in.position();
        where.byte += message.advance;
        where.column += message.advance;
        throw syntax_error(message.text, where, diag::Kind::Syntax, message.resume_here);
    }

private:
    static void leave(ParseState& st) {
        if constexpr (nests<Rule>::value) --st.nesting;
        if constexpr (opens_bracket<Rule>::value) st.open_brackets.pop_back();
    }
};

/// Error recovery: a statement or block item that fails is reported, the rest of it skipped,
/// and parsing goes on with the next one.
template <class Rule, bool InBlock>
struct control<grammar::recoverable<Rule, InBlock>>
    : tao::pegtl::normal<grammar::recoverable<Rule, InBlock>> {
    using base = tao::pegtl::normal<grammar::recoverable<Rule, InBlock>>;

    template <tao::pegtl::apply_mode A, tao::pegtl::rewind_mode M,
              template <typename...> class Action, template <typename...> class Control,
              class Input>
    static bool match(Input& in, ParseState& st) {
        st.doc_targets.clear(); // a trailing comment documents its own statement only
        const ParseState::Checkpoint saved = st.checkpoint();
        const auto start = in.iterator();
        try {
            const bool matched = base::template match<A, M, Action, Control>(in, st);
            // Every expression a statement parses is taken by the statement's actions.
            if (matched && st.stack_size() != saved.exprs) {
                throw diag::InternalError("the parser left " + std::to_string(st.stack_size()) +
                                          " expressions unused at line " +
                                          std::to_string(start.line));
            }
            return matched;
        } catch (const tao::pegtl::parse_error& error) {
            st.rollback(saved);
            in.iterator() = start;
            if (!st.report(error)) {
                in.bump(in.size()); // too many errors: stop
                return true;
            }
            // Go to the error, then past the rest of the broken statement.
            const std::size_t error_byte =
                error.positions().empty() ? start.byte : error.positions().front().byte;
            if (error_byte > start.byte) in.bump(std::min(error_byte - start.byte, in.size()));
            const auto* located = dynamic_cast<const syntax_error*>(&error);
            if (located == nullptr || !located->resume_here) {
                in.bump(statement_rest_length(std::string_view(in.current(), in.size()), InBlock));
            }
            if (in.byte() == start.byte) { // always make progress, or stop
                if (in.empty()) return false;
                in.bump(1);
            }
            return true;
        }
    }
};

} // namespace yamsc::parse
