#pragma once
// The text of the files `yamsc dlc` writes (docs/dlc.md): a TurbSim input per
// wind, an InflowWind file per wind and yaw misalignment, the batch manifest
// and the table of the cases.
#include "analysis/dlc_table.hpp"

#include <string>

namespace yamsc::analysis {

/// TurbSim's input (TurbSim v2 format, OpenFAST v5) of `w`: IECKAI, the
/// class's turbulence, the grid and the times of `o`.
std::string turbsim_input_text(const DlcOptions& o, const DlcWind& w);

/// An InflowWind v3.01 primary file: WindType 3 reading `bts` (relative to
/// the file's folder), PropagationDir = `yaw` [deg], the wind at the hub as
/// its output channel Wind1VelX.
std::string inflowwind_text(const DlcWind& w, double yaw, double hub_height,
                            const std::string& bts);

/// The manifest of `yamsc batch`. `paths` maps the inputs (model, parked
/// model, controller, its input, aero) to their names relative to the folder.
struct DlcPaths {
    std::string model, parked_model, controller, controller_input, aero;
};
std::string manifest_text(const DlcOptions& o, const DlcTable& t, const DlcPaths& paths);

/// One row per case: id, dlc, speed, turbulence model, seed, RandSeed1, yaw,
/// parked, the transient to drop (`yamsc loads --speeds` reads id and speed).
std::string table_text(const DlcOptions& o, const DlcTable& t);

} // namespace yamsc::analysis
