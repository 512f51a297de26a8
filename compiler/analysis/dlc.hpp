#pragma once
// `yamsc dlc`: a DLC table (dlc_table.hpp) written as a batch folder
// (docs/dlc.md): the winds' TurbSim inputs and .bts files, an InflowWind file
// per wind and yaw misalignment, the manifest and the table of the cases.
#include "analysis/dlc_table.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace yamsc::analysis {

int dlc(const DlcOptions& o, std::ostream& out, std::ostream& err);

/// A field to make: its TurbSim input and the .bts.
struct WindFile {
    std::string input, bts;
};

/// Writes each .bts from its input as `yamsc turbulence INPUT -o BTS` does,
/// `threads` at a time (0: one per core), a line on `err` as each starts.
void generate_winds(const std::vector<WindFile>& winds, int threads, std::ostream& err);

} // namespace yamsc::analysis
