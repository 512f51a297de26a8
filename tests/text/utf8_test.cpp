// UTF-8 sequence lengths (text/utf8.hpp), as the diagnostics and the parser's
// messages use them to keep characters whole.
#include "text/utf8.hpp"

#include <doctest/doctest.h>

#include <string>

using yamsc::text::utf8_continuation;
using yamsc::text::utf8_sequence_length;

TEST_CASE("utf8: the length of the sequence at the start, 0 when there is none") {
    CHECK(utf8_sequence_length("") == 0);
    CHECK(utf8_sequence_length("a") == 0);                 // ASCII is no multi-byte sequence
    CHECK(utf8_sequence_length("\xC3\xA9t\xC3\xA9") == 2); // é
    CHECK(utf8_sequence_length("\xE2\x82\xAC") == 3);      // €
    CHECK(utf8_sequence_length("\xF0\x9F\x98\x80x") == 4);
    CHECK(utf8_sequence_length("\xE2\x82") == 0);         // truncated
    CHECK(utf8_sequence_length("\xE2\x28\xA1") == 0);     // a second byte that is no continuation
    CHECK(utf8_sequence_length("\xA9") == 0);             // a stray continuation byte
    CHECK(utf8_sequence_length("\xC0\xAF") == 0);         // overlong
    CHECK(utf8_sequence_length("\xC1\xBF") == 0);         // overlong
    CHECK(utf8_sequence_length("\xF5\x80\x80\x80") == 0); // beyond U+10FFFF
    CHECK(utf8_sequence_length(std::string("\xC3\0", 2)) == 0);
    CHECK(utf8_continuation(0x80));
    CHECK(utf8_continuation(0xBF));
    CHECK_FALSE(utf8_continuation(0xC3));
    CHECK_FALSE(utf8_continuation('a'));
}
