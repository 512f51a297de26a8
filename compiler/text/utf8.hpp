#pragma once
// UTF-8 in source text: what diagnostics quote and what the parser's messages
// name must be whole characters.
#include <cstddef>
#include <string_view>

namespace yamsc::text {

/// The length (2 to 4) of the valid multi-byte UTF-8 sequence at the start of
/// `s`, or 0 when `s` does not start with one (ASCII, a stray continuation
/// byte, a truncated or invalid sequence).
std::size_t utf8_sequence_length(std::string_view s);

/// Whether `c` is a continuation byte (10xxxxxx) of a multi-byte sequence.
inline bool utf8_continuation(unsigned char c) {
    return (c & 0xC0) == 0x80;
}

} // namespace yamsc::text
