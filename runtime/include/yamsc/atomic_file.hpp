#pragma once
// Writing a file so that readers only ever see the old content or the complete
// new one: write `<path>.tmp.<pid>` beside it, then rename over the target.
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace yamsc::runtime {

/// Calls `write` with a stream on a temporary file next to `path` and renames it
/// to `path`. On any failure (cannot create, write error, `write` throws, rename
/// fails) the temporary file is removed, `path` is left as it was, and a
/// std::runtime_error naming the file and the reason is thrown (an exception
/// from `write` is rethrown as is).
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

/// The same for content already in memory.
void write_file_atomically(const std::string& path, const std::string& content);

/// Several files that belong together (a header and its source): every
/// temporary file is written before any target is replaced, so a failed write
/// leaves all targets as they were. Only the renames, in order, remain.
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files);

/// The temporary name used for `path` by this process.
std::string temporary_path_for(const std::string& path);

} // namespace yamsc::runtime
