#pragma once
// Beams from OpenFAST ElastoDyn tower and blade input files (docs/beam-preprocessing.md),
// read by formats/elastodyn.
// The beam runs along body z from the root; fore-aft and flap modes are along x,
// side-side and edge modes along y. Bad input gives located diagnostics and nullopt.
#include "beam/beam.hpp"
#include "diag/diagnostics.hpp"

#include <optional>

namespace yamsc::beam {

/// Mode names of a tower file: fa1, fa2, ss1, ss2.
const std::vector<std::string>& elastodyn_tower_modes();
/// Mode names of a blade file: flap1, flap2, edge1.
const std::vector<std::string>& elastodyn_blade_modes();

/// The tower of `file` (length from its base to its top) with `modes`, in that order.
std::optional<Beam> read_elastodyn_tower(const std::shared_ptr<const diag::SourceFile>& file,
                                         double length, const std::vector<std::string>& modes,
                                         diag::Diagnostics& diags);

/// The blade of `file` (length from root to tip: TipRad - HubRad) with `modes`, in order.
std::optional<Beam> read_elastodyn_blade(const std::shared_ptr<const diag::SourceFile>& file,
                                         double length, const std::vector<std::string>& modes,
                                         diag::Diagnostics& diags);

} // namespace yamsc::beam
