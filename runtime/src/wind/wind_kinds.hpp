#pragma once
// The kinds of wind field an InflowWind input file may name, one per WindType:
// each a function making the field (and its reference speed over time) from the
// file's entries. A new kind is one file defining its function and one line in
// wind_kinds.cpp's table; nothing else switches on WindType.
#include "yamsc/wind.hpp"

#include "wind/inflowwind_file.hpp"

namespace yamsc::runtime {

using WindKindOpen = WindInput (*)(wind::InflowWindFile& file);

struct WindKind {
    int wind_type;    // InflowWind's WindType
    const char* what; // for messages: "steady", "uniform wind file", ...
    WindKindOpen open;
};

/// The kind registered for `wind_type`, or nullptr.
const WindKind* wind_kind(int wind_type);
/// "1 (steady), 2 (uniform wind file)": the WindTypes registered.
std::string supported_wind_types();

// The kinds (one file each).
WindInput open_steady_wind(wind::InflowWindFile& file);  // uniform_kinds.cpp
WindInput open_uniform_wind(wind::InflowWindFile& file); // uniform_kinds.cpp
WindInput open_turbsim_wind(wind::InflowWindFile& file); // full_field_kinds.cpp
WindInput open_hawc_wind(wind::InflowWindFile& file);    // full_field_kinds.cpp

} // namespace yamsc::runtime
