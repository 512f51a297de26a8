#include "text/number.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace yamsc::text {
namespace {

/// std::to_chars into a string: 64 bytes hold every double in every format.
template <typename T, typename... Format> std::string chars(T value, Format... format) {
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value, format...);
    if (error != std::errc()) throw std::logic_error("std::to_chars: no room for a number");
    return std::string(buffer, end);
}

/// The shortest digits of a finite value, from to_chars' exponent notation
/// `-d.ddde+XX`: sign, digits without the point, decimal exponent of the first.
struct Decimal {
    std::string sign, digits;
    int exponent = 0;
};

Decimal decimal(const std::string& scientific) {
    Decimal d;
    std::size_t i = 0;
    if (scientific[0] == '-') {
        d.sign = "-";
        i = 1;
    }
    const std::size_t e = scientific.find('e');
    for (; i < e; ++i)
        if (scientific[i] != '.') d.digits += scientific[i];
    d.exponent = std::atoi(scientific.c_str() + e + 1);
    return d;
}

/// `d` in plain notation: 1500000, 0.00015, 12.5.
std::string plain(const Decimal& d) {
    const int n = static_cast<int>(d.digits.size());
    if (d.exponent < 0) return d.sign + "0." + std::string(-d.exponent - 1, '0') + d.digits;
    if (d.exponent >= n - 1) return d.sign + d.digits + std::string(d.exponent - n + 1, '0');
    return d.sign + d.digits.substr(0, d.exponent + 1) + "." + d.digits.substr(d.exponent + 1);
}

template <typename T> std::string general(T value, int plain_below) {
    std::string scientific = chars(value, std::chars_format::scientific);
    if (!std::isfinite(value)) return scientific;
    const Decimal d = decimal(scientific);
    if (d.exponent < -4 || d.exponent >= plain_below) return scientific;
    return plain(d);
}

} // namespace

std::string shortest(double value) {
    return chars(value);
}

std::string shortest_general(double value, int plain_below) {
    return general(value, plain_below);
}

std::string shortest_general(float value, int plain_below) {
    return general(value, plain_below);
}

std::string shortest_printf(double value, int min_precision) {
    // Below the normal range the digits printf rounds to at a precision are
    // not always the shortest (5e-324 reads back from 4.94065645841247e-324
    // too), so this is printf's search itself, not a layout of shortest().
    std::string text;
    for (int precision = std::max(min_precision, 1); precision <= 17; ++precision) {
        text = chars(value, std::chars_format::general, precision);
        double back = 0;
        std::from_chars(text.data(), text.data() + text.size(), back);
        if (back == value) break;
    }
    return text;
}

} // namespace yamsc::text
