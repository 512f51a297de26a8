#pragma once
// The manifest of `yamsc batch` (docs/batch.md): a CSV file with one case per
// row. Every field keeps its line and column so that a bad value is reported
// at its place in the manifest, as the model's diagnostics are.
#include "driver/commands.hpp"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace yamsc::analysis {

/// A located error of one case: `where` is `manifest:line:col`.
struct CaseError : std::runtime_error {
    CaseError(const std::string& where, const std::string& message)
        : std::runtime_error(where + ": error: " + message) {}
};

struct ManifestField {
    std::string text; // unquoted, surrounding blanks removed
    int line = 0, col = 0;
};

struct ManifestRow {
    int index = 0; // 0-based among the data rows (the shard key)
    int line = 0;
    std::vector<ManifestField> fields; // one per column
    std::string error;                 // malformed row (wrong field count, open quote), located
};

struct Manifest {
    std::string path;   // as given: the prefix of every location
    std::string folder; // models and wind files are relative to it
    std::vector<std::string> columns;
    std::vector<ManifestRow> rows;

    std::string where(int line, int col) const;
    /// The field of `column` in `row`, nullptr when the manifest has no such column.
    const ManifestField* field(const ManifestRow& row, const std::string& column) const;
};

/// Reads and checks the header (known columns, id/model/tmax/dt present).
/// Throws UserError (located) for a manifest that cannot be used at all;
/// a malformed data row only sets that row's `error`.
Manifest read_manifest(const std::string& path);

/// One case: its id, the model file (resolved against the manifest's folder)
/// and the options of `yamsc sim` it stands for (files resolved likewise).
struct BatchCase {
    std::string id;
    driver::SimOptions sim;
    /// Where each --set/--ic/--u name was given, to locate an unknown name.
    std::map<std::string, std::string> set_at, ic_at, u_at;
    std::string model_at, row_at;
    std::string coupling_at, interp_order_at, dt_out_at; // where given ("" when not)
    /// time_limit: the wall time after which the case is stopped [s]; 0: the
    /// batch's --case-time-limit (not in `text`: it does not change a result).
    double time_limit = 0;
    std::string text; // the row's content as name=value lines: what its digest covers
    /// The files read (their content too): the wind files, the rotor table,
    /// the controller library and its input file.
    std::vector<std::string> files;
};

/// The case of a well-formed row; throws CaseError at the offending field.
BatchCase case_of(const Manifest& m, const ManifestRow& row);

} // namespace yamsc::analysis
