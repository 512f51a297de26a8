#pragma once
// Where a model's data give a flexible body's sections (analysis/scene.hpp,
// BodySurface): the blades and the tower of a `load blade_elements` whose
// AeroDyn file `--aero` names (BlSpn, BlChord, BlTwist; TwrElev, TwrDiam).
#include "analysis/scene.hpp"

#include <string>
#include <vector>

namespace yamsc::analysis {

/// The surfaces of `m`'s blade-element blocks with the AeroDyn file `aero`
/// (none when the model has no such block or `aero` is empty). Throws
/// diag::UserError when the file cannot be read.
std::vector<BodySurface> scene_surfaces(const model::Model& m, const std::string& aero);

} // namespace yamsc::analysis
