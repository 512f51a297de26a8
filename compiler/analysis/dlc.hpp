#pragma once
// `yamsc dlc`: a DLC table (dlc_table.hpp) written as a batch folder
// (docs/dlc.md): the winds' TurbSim inputs and .bts files, an InflowWind file
// per wind and yaw misalignment, the manifest and the table of the cases.
#include "analysis/dlc_table.hpp"

#include <iosfwd>
#include <string>

namespace yamsc::analysis {

int dlc(const DlcOptions& o, std::ostream& out, std::ostream& err);

/// Writes the .bts of a TurbSim input (`yamsc turbulence INPUT -o BTS`).
void generate_bts(const std::string& turbsim_input, const std::string& bts);

} // namespace yamsc::analysis
