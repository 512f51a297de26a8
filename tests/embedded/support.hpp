#pragma once
// Helpers of the embedded-C tests: a scratch folder, shell commands, and the
// C output of a model as the command line writes it.
#include "test_files.hpp"

#include <string>

namespace embedded_test {

using test_support::read_file;
using test_support::write_file;

inline std::string scratch_dir(const std::string& name) {
    return test_support::scratch_dir("embedded_scratch", name);
}

/// The exit status of `command` run by the shell (-1 if it did not exit).
inline int run(const std::string& command) {
    return test_support::exit_status(command);
}

/// `yamsc <model> -o <dir>/<prefix>.c --header <prefix>.h --namespace <prefix>
/// --real <real> <options>`, model relative to the source tree; false (and the
/// messages in `log`) on failure.
bool generate_c(const std::string& model, const std::string& dir, const std::string& prefix,
                const std::string& real, std::string& log, const std::string& options = "");

} // namespace embedded_test
