#pragma once
// The output folder of `yamsc batch`: its default name, the folders made,
// what a killed or failed run leaves behind, and the paths compared with the
// batch's inputs.
#include <set>
#include <string>
#include <vector>

namespace yamsc::analysis {

/// The manifest's name without .csv, plus ".out".
std::string default_output_dir(const std::string& manifest);

/// Creates `path` and the folders above it; throws UserError when it cannot.
void make_dirs(const std::string& path);

/// Removes the temporary files a killed run left of the cases about to run
/// (`<id>.csv.tmp.<pid>`, `.records/<id>.tmp.<pid>`); another shard's are
/// not touched, since its cases have other ids.
void remove_leftovers(const std::string& dir, const std::vector<std::string>& ids);

/// A failed case leaves no result: a file from an earlier run of the row
/// would look like its result.
void forget(const std::string& dir, const std::string& id);

/// The path with links and dots resolved; as given when it does not exist.
std::string real_path(const std::string& path);

/// The input that the result of `id` would replace, or "" (inputs as real paths).
std::string replaced_input(const std::string& real_dir, const std::string& id,
                           const std::set<std::string>& inputs);

/// A whole file ("" when it cannot be read).
std::string read_all(const std::string& path);

} // namespace yamsc::analysis
