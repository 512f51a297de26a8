#pragma once
// The folder `sim --vtk DIR` writes (docs/visualization.md): DIR/<model>.pvd,
// DIR/<model>_<NNNNNN>.vtp per output row (formats/vtk) and DIR/<model>.csv.
#include "analysis/scene.hpp"
#include "analysis/sim_case.hpp"

#include <string>

namespace yamsc::analysis {

/// Throws diag::UsageError when `dir` exists and is not a folder: checked before
/// the run, whose files are named only once the model is read.
void check_scene_folder(const std::string& dir);

/// Writes the folder: `scene` drawn at every row of `with_scene` (the run with the
/// scene's outputs), and `run`'s CSV (sim's -o, with `channels`). The folder is
/// made if missing; a file of the run that exists must be a regular file (never a
/// link or a device) and no input of `inputs`. The .vtp and the .pvd are written
/// together (temporary files first), then the CSV.
void write_scene_folder(const std::string& dir, const std::string& model, const Scene& scene,
                        const runtime::SimulationResult& with_scene, const SimRun& run,
                        driver::Channels channels, const std::vector<driver::NamedFile>& inputs);

} // namespace yamsc::analysis
