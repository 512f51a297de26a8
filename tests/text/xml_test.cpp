// The one XML escaper: the five special characters and a line break, nothing else.
#include "text/xml.hpp"

#include <doctest/doctest.h>

using yamsc::text::xml_escaped;

TEST_CASE("xml_escaped quotes the five special characters and line breaks, and keeps the rest") {
    CHECK(xml_escaped("") == "");
    CHECK(xml_escaped("tower.TwHt [m]") == "tower.TwHt [m]");
    CHECK(xml_escaped("a<b & c>d") == "a&lt;b &amp; c&gt;d");
    CHECK(xml_escaped("\"it's\"") == "&quot;it&apos;s&quot;");
    CHECK(xml_escaped("two\nlines\t") == "two&#10;lines\t");
    CHECK(xml_escaped("θ' [rad/s]") == "θ&apos; [rad/s]"); // UTF-8 passes through
}
