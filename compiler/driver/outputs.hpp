#pragma once
// Outputs that never destroy what a command reads or its other outputs. Each
// command names its inputs and outputs with the role they play on its command
// line; before anything is written (and before the expensive stages where
// the inputs are known early), an output that is an input or another output
// is a usage error naming both. Two names are the same file when they reach
// the same device and inode (symbolic links, hard links, `./m.mbd`), or, for
// a name not created yet, the same place (its folder resolved, then the name).
// How each output is then written (regular file, link, device, FIFO) is the
// runtime's (yamsc/output_target.hpp).
#include "model/model.hpp"

#include <string>
#include <vector>

namespace yamsc::driver {

/// A file of a command: its role in messages ("-o", "the model") and its path.
struct NamedFile {
    std::string role;
    std::string path; ///< empty: not given, ignored
};

/// Throws UsageError when an output is one of `inputs` or another output, and
/// std::runtime_error when an output cannot be written at all (a folder, a
/// socket). Character devices (/dev/null, a terminal) are exempt from the
/// comparison: writing one destroys nothing, and /dev/stdin and /dev/stdout
/// are often the same terminal.
void check_outputs(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs);

/// A make rule for --depfile: `targets` depend on `dependencies` (paths
/// escaped as make and Ninja read them). Throws UsageError for a path with a
/// line break, which a depfile cannot express.
std::string make_rule(const std::vector<std::string>& targets,
                      const std::vector<std::string>& dependencies);

/// The data files the checked model read (SID, ElastoDyn), as inputs.
std::vector<NamedFile> data_files_of(const model::Model& m);

/// The SID files of `--sid body=file.sid,..`, as inputs.
std::vector<NamedFile> sid_files_of(const std::string& spec);

} // namespace yamsc::driver
