#include "parse/recovery.hpp"

namespace yamsc::parse {

std::size_t statement_rest_length(std::string_view rest, bool inside_block) {
    std::size_t depth = 0; // brackets and braces opened after the error
    std::size_t i = 0;
    while (i < rest.size()) {
        const char c = rest[i];
        if (c == '"') { // a string ends at its quote or at the end of the line
            for (++i; i < rest.size() && rest[i] != '"' && rest[i] != '\n'; ++i) {
                if (rest[i] == '\\' && i + 1 < rest.size() && rest[i + 1] != '\n') ++i;
            }
            if (i < rest.size() && rest[i] == '"') ++i;
            continue;
        }
        if (c == '#') {
            while (i < rest.size() && rest[i] != '\n') ++i;
            continue;
        }
        if (c == '(' || c == '{') {
            ++depth;
        } else if (c == ')') {
            if (depth > 0) --depth;
        } else if (c == '}') {
            if (depth > 0)
                --depth;
            else if (inside_block)
                return i;
        } else if ((c == '\n' || c == ';') && depth == 0) {
            return i;
        }
        ++i;
    }
    return i;
}

} // namespace yamsc::parse
