#include "embedded/support.hpp"

namespace embedded_test {

bool generate_c(const std::string& model, const std::string& dir, const std::string& prefix,
                const std::string& real, std::string& log, const std::string& options) {
    const std::string err = dir + "/" + prefix + ".yamsc.log";
    const std::string command = std::string(YAMSC_EXE) + " " + YAMSC_SOURCE_DIR + "/" + model +
                                " -o " + dir + "/" + prefix + ".c --header " + dir + "/" + prefix +
                                ".h --namespace " + prefix + " --real " + real + " " + options +
                                " 2> " + err;
    if (run(command) == 0) return true;
    log += "$ " + command + "\n" + read_file(err);
    return false;
}

} // namespace embedded_test
