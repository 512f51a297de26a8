#pragma once
// Writing a file so that readers only ever see the old content or the complete
// new one: write `<path>.tmp.<pid>` beside it, then rename over the target.
#include <functional>
#include <ostream>
#include <string>

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

/// The temporary name used for `path` by this process.
std::string temporary_path_for(const std::string& path);

} // namespace yamsc::runtime
