#pragma once
// What the ElastoDyn tower and blade readers share: the station table and the modes.
#include "beam/beam.hpp"
#include "beam/elastodyn_file.hpp"

namespace yamsc::beam {

/// How one ElastoDyn mode is described in its file.
struct EdModeKeys {
    std::string name;    // as requested: fa1, flap1, ...
    std::string shape;   // coefficient keys: shape(2) .. shape(6)
    std::string damping; // damping ratio in percent
    std::string tuner;   // modal stiffness tuner, or "" if the file has none
    int direction = 0;   // 0: x, 1: y
};

/// Appends the `requested` modes to `beam`; false after reporting errors.
bool read_ed_modes(const ElastoDynFile& f, const std::vector<std::string>& requested,
                   const std::vector<EdModeKeys>& known, Beam& beam, diag::Diagnostics& diags);

/// The rows of the distributed-properties table: `count_key` rows under the header
/// row that starts with `columns[0]`; values[row][i] is the column named columns[i].
/// The first column (span fraction) must rise strictly from 0 to 1.
struct EdStations {
    std::vector<std::vector<double>> values;
    std::vector<int> lines;
};
std::optional<EdStations> read_ed_stations(const ElastoDynFile& f, const std::string& count_key,
                                           const std::vector<std::string>& columns,
                                           diag::Diagnostics& diags);

/// Reports a length that is not > 0; true if it is fine.
bool check_ed_length(const ElastoDynFile& f, double length, diag::Diagnostics& diags);

} // namespace yamsc::beam
