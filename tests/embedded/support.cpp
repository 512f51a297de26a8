#include "embedded/support.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace embedded_test {

namespace fs = std::filesystem;

std::string scratch_dir(const std::string& name) {
    const fs::path dir = fs::path(YAMSC_TEST_BINARY_DIR) / "embedded_scratch" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

int run(const std::string& command) {
    const int status = std::system(command.c_str());
    return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_file(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

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
