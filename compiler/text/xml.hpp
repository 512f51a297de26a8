#pragma once
// Text inside XML that yamsc writes (a unit's modelDescription.xml, a run's
// .pvd): one escaper, so that every writer quotes names and descriptions alike.
#include <string>
#include <string_view>

namespace yamsc::text {

/// `s` as XML character data or a quoted attribute value: the five special
/// characters as entities and a line break as `&#10;` (kept by attribute
/// normalization, which would turn a bare one into a blank).
std::string xml_escaped(std::string_view s);

} // namespace yamsc::text
