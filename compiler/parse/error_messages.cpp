#include "parse/error_messages.hpp"

#include "ast/keywords.hpp"
#include "diag/diagnostics.hpp"
#include "text/utf8.hpp"

#include <cstdio>

namespace yamsc::parse {
namespace {

bool is_identifier_first(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_identifier_other(char c) {
    return is_identifier_first(c) || (c >= '0' && c <= '9');
}
bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\f' || c == '\v';
}

/// The identifier at the start of `rest`, or "".
std::string_view leading_word(std::string_view rest) {
    if (rest.empty() || !is_identifier_first(rest[0])) return {};
    std::size_t n = 1;
    while (n < rest.size() && is_identifier_other(rest[n])) ++n;
    return rest.substr(0, n);
}

/// Quotes a word for a message, shortened if it is very long.
std::string quoted(std::string_view word) {
    constexpr std::size_t max_shown = 40;
    if (word.size() > max_shown) return "'" + std::string(word.substr(0, max_shown)) + "...'";
    return "'" + std::string(word) + "'";
}

std::string describe_char(std::string_view rest) {
    const auto c = static_cast<unsigned char>(rest[0]);
    if (c > 0x20 && c < 0x7F) return quoted(rest.substr(0, 1));
    if (const std::size_t n = text::utf8_sequence_length(rest)) return quoted(rest.substr(0, n));
    char hex[16];
    std::snprintf(hex, sizeof hex, "byte 0x%02X", static_cast<unsigned>(c));
    return hex;
}

/// For a block of `key = value` lines whose item at `rest` is neither a property nor one of
/// `keywords`.
ErrorMessage unknown_property_item(std::string_view rest, const std::vector<std::string>& keywords,
                                   const ParseState& st) {
    const std::string_view word = leading_word(rest);
    if (word.empty()) {
        return {fill_message("expected a property 'name = value', found {found}", rest, st)};
    }
    const std::string suggestion = diag::closest_name(word, keywords);
    if (!suggestion.empty()) {
        return {"unknown item " + quoted(word) + " (did you mean '" + suggestion + "'?)"};
    }
    std::size_t after = word.size();
    while (after < rest.size() && is_blank(rest[after])) ++after;
    return {"expected '=' after property name " + quoted(word) + ", found " +
                describe_found(rest.substr(after)),
            after};
}

} // namespace

std::string describe_found(std::string_view rest) {
    if (rest.empty()) return "end of file";
    if (rest[0] == '\n' || rest.substr(0, 2) == "\r\n") return "end of line";
    if (is_blank(rest[0])) return "a blank";
    if (rest[0] == '"') return "a string";
    if (rest[0] == '#') return "a comment";
    if (const std::string_view word = leading_word(rest); !word.empty()) return quoted(word);
    if ((rest[0] >= '0' && rest[0] <= '9') ||
        (rest[0] == '.' && rest.size() > 1 && rest[1] >= '0' && rest[1] <= '9')) {
        std::size_t n = 1;
        while (n < rest.size() && (is_identifier_other(rest[n]) || rest[n] == '.')) ++n;
        return quoted(rest.substr(0, n));
    }
    if (rest.substr(0, 2) == "->") return "'->'";
    return describe_char(rest);
}

std::string fill_message(std::string_view text, std::string_view rest, const ParseState& st) {
    std::string out;
    out.reserve(text.size() + 32);
    for (std::size_t i = 0; i < text.size();) {
        if (text.substr(i, 7) == "{found}") {
            out += describe_found(rest);
            i += 7;
        } else if (text.substr(i, 6) == "{open}") {
            out += st.open_brackets.empty() ? std::string("?") : line_col(st.open_brackets.back());
            i += 6;
        } else {
            out += text[i++];
        }
    }
    return out;
}

ErrorMessage error_message<grammar::string_close>::compose(std::string_view rest,
                                                           const ParseState&) {
    if (rest.size() < 2 || rest[0] != '\\' || rest[1] == '\n') {
        return {"unterminated string: expected '\"' before the end of the line"};
    }
    rest.remove_prefix(1);
    if (rest[0] > 0x20 && rest[0] < 0x7F) {
        return {"unknown escape '\\" + std::string(1, rest[0]) +
                "' in a string (only \\\" and \\\\ are allowed)"};
    }
    return {"unknown escape in a string: '\\' followed by " + describe_char(rest)};
}

ErrorMessage error_message<grammar::unknown_statement>::compose(std::string_view rest,
                                                                const ParseState& st) {
    if (const std::string_view word = leading_word(rest); !word.empty()) {
        return {"unknown statement " + quoted(word) +
                diag::did_you_mean(word, ast::statement_keywords())};
    }
    if (rest[0] == '}') return {"unexpected '}': no block is open"};
    if (rest[0] == '{') return {"unexpected '{': a block starts on the line of its statement"};
    return {fill_message("expected a statement, found {found}", rest, st)};
}

ErrorMessage error_message<grammar::unknown_rigid_item>::compose(std::string_view rest,
                                                                 const ParseState& st) {
    return unknown_property_item(rest, {}, st);
}

ErrorMessage error_message<grammar::unknown_flexible_item>::compose(std::string_view rest,
                                                                    const ParseState& st) {
    return unknown_property_item(rest, ast::flexible_item_keywords(), st);
}

ErrorMessage error_message<grammar::unknown_beam_item>::compose(std::string_view rest,
                                                                const ParseState& st) {
    return unknown_property_item(rest, ast::beam_item_keywords(), st);
}

ErrorMessage error_message<grammar::unknown_joint_item>::compose(std::string_view rest,
                                                                 const ParseState& st) {
    const std::string_view word = leading_word(rest);
    if (word.empty()) {
        return {fill_message("expected a joint step (at, translate, rotate, free) or "
                             "'option = value', found {found}",
                             rest, st)};
    }
    const std::string suggestion = diag::closest_name(word, ast::joint_step_keywords());
    if (!suggestion.empty()) {
        return {"unknown joint step " + quoted(word) + " (did you mean '" + suggestion + "'?)"};
    }
    return {"unknown joint step " + quoted(word) +
            ": expected at, translate, rotate, free or 'option = value'"};
}

ErrorMessage error_message<grammar::unknown_linearize_item>::compose(std::string_view rest,
                                                                     const ParseState& st) {
    return {
        fill_message("expected 'name = value' in the linearize block, found {found}", rest, st)};
}

ErrorMessage error_message<grammar::unknown_initial_item>::compose(std::string_view rest,
                                                                   const ParseState& st) {
    return {fill_message("expected 'name = value' in the initial block, found {found}", rest, st)};
}

ErrorMessage error_message<grammar::unknown_load_item>::compose(std::string_view rest,
                                                                const ParseState& st) {
    return {fill_message("expected 'role = value' in the load block, found {found}", rest, st)};
}

ErrorMessage error_message<grammar::unknown_constraint_item>::compose(std::string_view rest,
                                                                      const ParseState& st) {
    return {fill_message("expected 'role = value' in the constraint, found {found}", rest, st)};
}

} // namespace yamsc::parse
