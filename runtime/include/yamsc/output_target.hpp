#pragma once
// What an output path names, and so how it must be written. Renaming a
// temporary file over the path is right for a regular file and wrong for
// everything else: it would put a regular file where a device, a pipe or a
// symbolic link was. So:
// - a regular file, or nothing yet: replaced atomically (a temporary file in
//   its folder, then rename);
// - a symbolic link: followed to its final target, which is then written as
//   above; the link stays a link;
// - a character device (/dev/null, a terminal) or a FIFO: opened for writing
//   and written in place, with no rename and no truncation;
// - a folder, a socket or a block device: refused.
#include <string>

namespace yamsc::runtime {

struct OutputTarget {
    enum class Kind {
        file,  ///< replace `path` atomically
        stream ///< write into the device or FIFO in place
    };
    Kind kind = Kind::file;
    /// Where the bytes go. For `file` the final target of any symbolic links
    /// (the temporary file goes beside it); for `stream` the path as given.
    std::string path;
};

/// Classifies `path` as it is now. Throws std::runtime_error "cannot write
/// '<path>': ..." for a folder, a socket, a block device or a loop of links.
/// A path that cannot be reached (a missing folder) is a `file`: creating its
/// temporary file then reports why.
OutputTarget resolve_output(const std::string& path);

} // namespace yamsc::runtime
