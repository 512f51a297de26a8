#pragma once
// Numbers of the SID text format: reading the literals the grammar accepts (C and Fortran
// exponents) and writing doubles so that they read back exactly.
#include <optional>
#include <string>
#include <string_view>

namespace yamsc::sid {

/// The value of a real literal of sid/grammar.hpp (`1.5`, `-2.D+03`, `nan`). Overflow
/// gives an infinity, underflow a zero; std::nullopt if `text` is not such a literal.
std::optional<double> parse_real(std::string_view text);

/// The value of an integer literal (`12`, `-3`); values beyond the range of long long are
/// clamped to it. std::nullopt if `text` is not an integer literal.
std::optional<long long> parse_integer(std::string_view text);

/// The shortest text that reads back as exactly `value` (`0.1`, `1e-300`, `-0`, `nan`).
std::string format_real(double value);

} // namespace yamsc::sid
