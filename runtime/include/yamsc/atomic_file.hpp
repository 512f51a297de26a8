#pragma once
// Writing an output so that readers only ever see the old content or the
// complete new one, and so that writing never replaces what the path names
// with something else (yamsc/output_target.hpp): a regular file (or a new one)
// is written as `<target>.tmp.<pid>` beside it and renamed over it; a symbolic
// link is followed and its final target replaced that way, so the link stays;
// a character device or a FIFO is written in place; a folder, a socket or a
// block device is refused.
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace yamsc::runtime {

/// Calls `write` with a stream on a temporary file next to the target of `path`
/// and renames it to that target, keeping the permission bits of the file it
/// replaces (a device or FIFO: `write` streams into it directly). On any failure
/// (cannot create, write error, `write` throws, rename fails) the temporary file
/// is removed, the target is left as it was, and a std::runtime_error naming
/// `path` and the reason is thrown (an exception from `write` is rethrown as is).
/// A device or FIFO may have received part of the content by then.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write);

/// The same for content already in memory.
void write_file_atomically(const std::string& path, const std::string& content);

/// Several files that belong together (a header and its source): every
/// temporary file is written before any target is replaced, so a failed write
/// leaves all targets as they were. Only the renames (and the writes into
/// devices or FIFOs), in order, remain.
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files);

/// The temporary name used for the regular file `path` by this process.
std::string temporary_path_for(const std::string& path);

} // namespace yamsc::runtime
