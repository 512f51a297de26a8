#pragma once
// The shortest decimal text that reads back as the same floating-point number,
// on std::to_chars (locale-independent, exact). One set of digits, three
// layouts: the callers (generated code, JSON, SID files, .mbd files, CSV) add
// their own decoration (a C literal's ".0", JSON's null for NaN) around it.
#include <string>

namespace yamsc::text {

/// The shortest decimal that reads back as exactly `value`, as std::to_chars
/// writes it: plain or exponent notation, whichever is shorter, plain on a tie
/// (`0.1`, `100`, `1e+06`, `1e-05`, `-0`, `inf`, `-inf`, `nan`).
std::string shortest(double value);

/// The same digits in printf's %g layout: plain notation when the decimal
/// exponent of the first digit is in [-4, plain_below) (`0.0001`, `1000000`),
/// else exponent notation (`1e-05`, `1.5e+16`); no trailing zeros or point.
/// `plain_below` 16 is fmt's and Python's repr layout; non-finite values as
/// shortest().
std::string shortest_general(double value, int plain_below = 16);
/// The float overload: the shortest text that reads back as the same float.
std::string shortest_general(float value, int plain_below = 16);

/// printf("%.*g", P, value) for the smallest P >= min_precision that reads
/// back as `value` (17 for NaN): for a normal double the shortest digits,
/// plain for exponents in [-4, P).
std::string shortest_printf(double value, int min_precision);

} // namespace yamsc::text
