// ASCII upper case (text/ascii.hpp): the input readers' keys compared without
// case, whatever the locale; bytes outside a-z, UTF-8 included, unchanged.
#include "text/ascii.hpp"

#include <doctest/doctest.h>

#include <clocale>

TEST_CASE("ascii_upper: a-z only") {
    using yamsc::text::ascii_upper;
    CHECK(ascii_upper("Line Dictionary") == "LINE DICTIONARY");
    CHECK(ascii_upper("ranlux 2.5e-3 [m]") == "RANLUX 2.5E-3 [M]");
    CHECK(ascii_upper("") == "");
    // ß and é (UTF-8) stay as they are, byte for byte.
    CHECK(ascii_upper("stra\xc3\x9f"
                      "e caf\xc3\xa9") == "STRA\xc3\x9f"
                                          "E CAF\xc3\xa9");
    // A locale that upper-cases Latin-1 bytes changes nothing here.
    std::setlocale(LC_CTYPE, "C.UTF-8");
    CHECK(ascii_upper("\xe9t\xe9") == "\xe9T\xe9");
    std::setlocale(LC_CTYPE, "C");
}
