#include "sid/numbers.hpp"

#include "text/number.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

namespace yamsc::sid {

std::optional<double> parse_real(std::string_view text) {
    // std::from_chars: locale-independent, but it takes no '+' and no Fortran `D` exponent.
    std::string literal(text);
    bool negative = false;
    if (!literal.empty() && (literal[0] == '+' || literal[0] == '-')) {
        negative = literal[0] == '-';
        literal.erase(0, 1);
    }
    bool negative_exponent = false;
    for (std::size_t i = 0; i < literal.size(); ++i) {
        if (literal[i] == 'd' || literal[i] == 'D') literal[i] = 'e';
        if ((literal[i] == 'e' || literal[i] == 'E') && i + 1 < literal.size() &&
            literal[i + 1] == '-') {
            negative_exponent = true;
        }
    }
    if (literal.empty() || literal[0] == '-' || literal[0] == '+') return std::nullopt;
    double value = 0;
    const char* end = literal.data() + literal.size();
    const auto [ptr, ec] = std::from_chars(literal.data(), end, value);
    if (ec == std::errc::result_out_of_range) {
        value = negative_exponent ? 0.0 : std::numeric_limits<double>::infinity();
    } else if (ec != std::errc() || ptr != end) {
        return std::nullopt;
    }
    return negative ? -value : value;
}

std::optional<long long> parse_integer(std::string_view text) {
    bool negative = false;
    if (!text.empty() && (text[0] == '+' || text[0] == '-')) {
        negative = text[0] == '-';
        text.remove_prefix(1);
    }
    if (text.empty()) return std::nullopt;
    long long value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec == std::errc::result_out_of_range) {
        value = std::numeric_limits<long long>::max();
    } else if (ec != std::errc() || ptr != end) {
        return std::nullopt;
    }
    return negative ? -value : value;
}

std::string format_real(double value) {
    if (std::isnan(value)) return "nan"; // never "-nan"
    return text::shortest(value);
}

} // namespace yamsc::sid
