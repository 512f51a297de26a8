// Small text helpers of the actions.
#include "parse/actions.hpp"

namespace yamsc::parse {

std::string unescape(std::string_view body) {
    std::string out;
    out.reserve(body.size());
    for (std::size_t i = 0; i < body.size(); ++i) {
        if (body[i] == '\\' && i + 1 < body.size()) ++i; // the grammar admits only \" and \\.
        out += body[i];
    }
    return out;
}

int parse_order(const std::string& digits, const tao::pegtl::position& where,
                const ParseState& st) {
    long long value = 0;
    for (const char c : digits) {
        value = value * 10 + (c - '0');
        if (value > INT_MAX)
            st.fail("order is too large (at most " + std::to_string(INT_MAX) + ")", where,
                    diag::Kind::Limit);
    }
    return static_cast<int>(value);
}

std::string comment_text(std::string_view comment) {
    if (!comment.empty() && comment.front() == '#') comment.remove_prefix(1);
    const auto is_space = [](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
    };
    while (!comment.empty() && is_space(comment.front())) comment.remove_prefix(1);
    while (!comment.empty() && is_space(comment.back())) comment.remove_suffix(1);
    return std::string(comment);
}

} // namespace yamsc::parse
