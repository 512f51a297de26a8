#pragma once
// A MAP++ input file as the runtime's quasi-static mooring lines
// (yamsc/mooring/mooring_system.hpp): line types to weights in water, `depth`
// to the anchors' Z, the REPEAT option's copies, as MAP++ initializes them
// (docs/mooring.md lists each convention).
#include "diag/diagnostics.hpp"
#include "map/map_input.hpp"
#include "yamsc/mooring/mooring_system.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace yamsc::analysis {

/// What MAP++ takes from the glue code: SeaState's water depth and density
/// (WtrDpth, WtrDens) and the gravity of the deck.
struct MooringEnvironment {
    double water_depth = 0;      // [m], > 0
    double water_density = 1025; // [kg/m^3]
    double gravity = 9.80665;    // [m/s^2]
};

/// The lines of a MAP++ file read already; errors located in it, nullopt after one.
/// Only lines from a Fix node (the anchor) to a Vessel node (the fairlead, in the
/// body's axes) are supported: Connect nodes (line networks) are refused.
std::optional<std::vector<runtime::mooring::Line>>
mooring_lines(const map::MapInput& input, const MooringEnvironment& environment,
              diag::Diagnostics& diags);

/// Reads the file and converts it; a file that cannot be read is an error at no line.
std::optional<std::vector<runtime::mooring::Line>>
read_map_mooring(const std::filesystem::path& file, const MooringEnvironment& environment,
                 diag::Diagnostics& diags);

} // namespace yamsc::analysis
