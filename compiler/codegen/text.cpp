#include "codegen/text.hpp"

#include <cstdio>

namespace yamsc::codegen {

std::string c_string_literal(std::string_view text) {
    std::string out = "\"";
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '"' || c == '\\' || c == '?') {
            out += '\\';
            out += ch;
        } else if (c < 0x20 || c >= 0x7f) {
            char octal[8]; // three octal digits: an escape that cannot swallow what follows
            std::snprintf(octal, sizeof octal, "\\%03o", static_cast<unsigned>(c));
            out += octal;
        } else {
            out += ch;
        }
    }
    return out + "\"";
}

std::string comment_quote(std::string_view text) {
    std::string out = "\"";
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        out += (c < 0x20 || c == 0x7f) ? ' ' : ch;
    }
    return out + "\"";
}

bool is_c_identifier(std::string_view text) {
    if (text.empty()) return false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
        const bool digit = c >= '0' && c <= '9';
        if (!letter && !(digit && i > 0)) return false;
    }
    return true;
}

bool is_cpp_namespace(std::string_view text) {
    std::size_t start = 0;
    while (true) {
        const std::size_t sep = text.find("::", start);
        if (!is_c_identifier(text.substr(start, sep - start))) return false;
        if (sep == std::string_view::npos) return true;
        start = sep + 2;
    }
}

} // namespace yamsc::codegen
