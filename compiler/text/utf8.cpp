#include "text/utf8.hpp"

namespace yamsc::text {

std::size_t utf8_sequence_length(std::string_view s) {
    if (s.empty()) return 0;
    const auto lead = static_cast<unsigned char>(s[0]);
    std::size_t n = 0;
    if (lead >= 0xC2 && lead <= 0xDF)
        n = 2;
    else if (lead >= 0xE0 && lead <= 0xEF)
        n = 3;
    else if (lead >= 0xF0 && lead <= 0xF4)
        n = 4;
    if (n == 0 || s.size() < n) return 0;
    for (std::size_t i = 1; i < n; ++i)
        if (!utf8_continuation(static_cast<unsigned char>(s[i]))) return 0;
    return n;
}

} // namespace yamsc::text
