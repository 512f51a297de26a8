#pragma once
// Helpers of the embedded-C tests: a scratch folder, shell commands, and the
// C output of a model as the command line writes it.
#include <string>

namespace embedded_test {

/// A fresh folder under the test's binary folder.
std::string scratch_dir(const std::string& name);

/// The exit status of `command` run by the shell (-1 if it did not exit).
int run(const std::string& command);

std::string read_file(const std::string& path);
void write_file(const std::string& path, const std::string& text);

/// `yamsc <model> -o <dir>/<prefix>.c --header <prefix>.h --namespace <prefix>
/// --real <real> <options>`, model relative to the source tree; false (and the
/// messages in `log`) on failure.
bool generate_c(const std::string& model, const std::string& dir, const std::string& prefix,
                const std::string& real, std::string& log, const std::string& options = "");

} // namespace embedded_test
