#pragma once
// Files and commands as the tests that run yamsc or a compiler need them:
// a fresh scratch folder under the test build folder, whole-file reads and
// writes, a shell command's exit status, and the writer's temporary files left in a
// folder.
#include <cstdlib>
#include <dirent.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace test_support {

/// A fresh (emptied) folder YAMSC_TEST_BINARY_DIR/<area>/<name>.
inline std::string scratch_dir(const std::string& area, const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(YAMSC_TEST_BINARY_DIR) / area / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

inline std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void write_file(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

/// `s` with every `from` replaced by `to`.
inline std::string replace_all(std::string s, const std::string& from, const std::string& to) {
    for (auto pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size()))
        s.replace(pos, from.size(), to);
    return s;
}

/// The exit status of `command` run by the shell (-1 if it did not exit).
inline int exit_status(const std::string& command) {
    const int status = std::system(command.c_str());
    return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Names in `dir` that contain `.tmp.` (the writer's temporary files).
inline std::vector<std::string> temporaries(const std::string& dir) {
    std::vector<std::string> out;
    if (DIR* d = opendir(dir.c_str())) {
        while (dirent* e = readdir(d))
            if (std::string(e->d_name).find(".tmp.") != std::string::npos)
                out.emplace_back(e->d_name);
        closedir(d);
    }
    return out;
}

} // namespace test_support
