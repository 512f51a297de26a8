#pragma once
// A MoorDyn input file as the runtime's quasi-static mooring lines
// (yamsc/mooring/mooring_system.hpp): each line from a Fixed point (the anchor)
// to a Vessel/Coupled point (the fairlead, in the body's axes), its weight in
// water as MoorDyn computes it (docs/mooring.md, "MoorDyn's file").
#include "analysis/map_mooring.hpp"
#include "diag/diagnostics.hpp"
#include "moordyn/moordyn_input.hpp"
#include "yamsc/mooring/mooring_system.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace yamsc::analysis {

/// The lines of a MoorDyn file read already; errors located in it, nullopt after
/// one. The file's options g, rhoW and WtrDpth win over `environment` (as in
/// MoorDyn, where the glue code's values are the defaults). Warns at the OPTIONS
/// header that the lines run quasi-static. Refused at their line: Free points
/// (line networks), bodies, rods, points with mass or volume, visco-elastic EA,
/// anchors off the seabed.
std::optional<std::vector<runtime::mooring::Line>>
moordyn_lines(const moordyn::MoorDynInput& input, const MooringEnvironment& environment,
              diag::Diagnostics& diags);

/// Reads the file and converts it; a file that cannot be read is an error at no line.
std::optional<std::vector<runtime::mooring::Line>>
read_moordyn_mooring(const std::filesystem::path& file, const MooringEnvironment& environment,
                     diag::Diagnostics& diags);

} // namespace yamsc::analysis
