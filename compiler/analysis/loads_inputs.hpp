#pragma once
// Where `yamsc loads` finds its runs: a `yamsc batch` output folder (its summary
// and one CSV per finished case), and the mean wind speed of each run given in a
// table (`--speeds`: a batch manifest or any CSV with an `id` column and a
// numeric `speed` or `wind` column).
#include <map>
#include <string>
#include <vector>

namespace yamsc::analysis {

struct BatchRuns {
    std::vector<std::string> files;   ///< OUTDIR/<id>.csv of each case that finished
    std::vector<std::string> skipped; ///< "id: reason" of each failed case
    std::string summary;              ///< the summary file read
};

/// Throws UserError when the folder has no summary.csv (a sharded batch not merged).
BatchRuns batch_runs(const std::string& dir);

/// id -> speed [m/s]; a located UserError on a malformed table.
std::map<std::string, double> read_speeds(const std::string& path);

} // namespace yamsc::analysis
