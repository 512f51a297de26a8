#include "text/ascii.hpp"

namespace yamsc::text {

std::string ascii_upper(std::string_view s) {
    std::string u(s);
    for (char& c : u)
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    return u;
}

} // namespace yamsc::text
