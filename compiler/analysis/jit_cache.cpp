#include "analysis/jit_cache.hpp"

#include "driver/derivation_loader.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace yamsc::analysis {

using driver::derivation_module_path;

namespace {

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

void make_dirs(const std::string& path) {
    for (std::size_t pos = 1; pos <= path.size(); ++pos) {
        if (pos == path.size() || path[pos] == '/') {
            const std::string part = path.substr(0, pos);
            if (::mkdir(part.c_str(), 0755) != 0 && errno != EEXIST)
                throw std::runtime_error("cannot create the cache folder '" + part + "'");
        }
    }
}

/// The file a command name runs: itself when it has a slash, else the first
/// executable of that name on PATH; links resolved. Empty when not found.
std::string resolve_program(const std::string& name) {
    std::vector<std::string> candidates;
    if (name.find('/') != std::string::npos) {
        candidates.push_back(name);
    } else {
        std::stringstream path(env("PATH"));
        for (std::string dir; std::getline(path, dir, ':');)
            if (!dir.empty()) candidates.push_back(dir + "/" + name);
    }
    for (const std::string& c : candidates) {
        if (::access(c.c_str(), X_OK) != 0) continue;
        char resolved[PATH_MAX];
        if (::realpath(c.c_str(), resolved)) return resolved;
    }
    return "";
}

std::string file_stamp(const std::string& path) {
    struct stat st {};
    if (path.empty() || ::stat(path.c_str(), &st) != 0) return "?";
    return path + " " + std::to_string(st.st_size) + " " + std::to_string(st.st_mtime) + "." +
           std::to_string(st.st_mtim.tv_nsec);
}

// Before any compile was recorded in a cache: g++ 12 at -O2 on generated model
// code on a quiet 2-core machine, in seconds per MB (every routine of the
// 16-DOF turbine, 4.7 MB in 85 s, docs/benchmarks.md).
constexpr double default_seconds_per_megabyte = 18.0;
constexpr std::size_t compiles_considered = 20;
const char* const record_name = "compile-times.tsv";

} // namespace

std::string cache_folder(const std::string& configured) {
    if (!configured.empty()) return configured;
    if (auto d = env("YAMSC_CACHE_DIR"); !d.empty()) return d;
    if (auto d = env("XDG_CACHE_HOME"); !d.empty()) return d + "/yamsc";
    if (auto d = env("HOME"); !d.empty()) return d + "/.cache/yamsc";
    return "/tmp/yamsc-cache-" + std::to_string(::getuid());
}

std::string compiler_of(const std::string& configured) {
    if (!configured.empty()) return configured;
    if (auto c = env("YAMSC_CXX"); !c.empty()) return c;
    if (auto c = env("CXX"); !c.empty()) return c;
#ifdef YAMSC_CXX_COMPILER
    if (std::string c = YAMSC_CXX_COMPILER; !c.empty() && ::access(c.c_str(), X_OK) == 0) return c;
#endif
    return "c++";
}

std::string compiler_identity(const std::string& compiler) {
    const std::string resolved = resolve_program(compiler);
    return compiler + " -> " + (resolved.empty() ? std::string("?") : file_stamp(resolved));
}

std::string file_identity(const std::string& path) {
    char resolved[PATH_MAX];
    if (path.empty() || !::realpath(path.c_str(), resolved)) return path + " -> ?";
    return path + " -> " + file_stamp(resolved);
}

std::string program_identity() {
    char self[PATH_MAX];
    const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
    const std::string exe = n > 0 ? std::string(self, static_cast<std::size_t>(n)) : "";
    std::string id = std::string("yamsc ") + YAMSC_VERSION + " " + file_stamp(exe);
    // yamsc inside another program (the Python module): the object this code
    // is in is the build that matters, not the interpreter.
    Dl_info info{};
    char object[PATH_MAX];
    if (::dladdr(reinterpret_cast<void*>(&program_identity), &info) && info.dli_fname &&
        ::realpath(info.dli_fname, object) && exe != object)
        id += " in " + file_stamp(object);
    // The equations come from the derivation module: a rebuilt module is
    // another compiler even when the program is not.
    id += " deriving with " + file_stamp(derivation_module_path());
    return id;
}

std::string cpu_identity() {
    std::ifstream in("/proc/cpuinfo");
    std::string id;
    for (std::string line;
         std::getline(in, line) && line.find_first_not_of(" \t") != std::string::npos;) {
        // The first processor's block: its model and what it can execute.
        for (const char* key : {"vendor_id", "model name", "flags", "Features", "CPU part"})
            if (line.rfind(key, 0) == 0) id += line + "\n";
    }
    return id;
}

ModelCache::ModelCache(std::string folder) : folder_(std::move(folder)) {
    make_dirs(folder_);
}

std::string ModelCache::library_path(const std::string& model_name, const std::string& key) const {
    return folder_ + "/" + model_name + "-" + key + ".so";
}

CompileEstimate ModelCache::estimate(std::size_t bytes) const {
    std::ifstream in(folder_ + "/" + record_name);
    std::vector<double> rates; // seconds per byte
    double b = 0, s = 0;
    while (in >> b >> s)
        if (b > 0 && s > 0) rates.push_back(s / b);
    if (rates.empty())
        return {default_seconds_per_megabyte * static_cast<double>(bytes) / 1e6, false};
    if (rates.size() > compiles_considered)
        rates.erase(rates.begin(), rates.end() - static_cast<long>(compiles_considered));
    std::nth_element(rates.begin(), rates.begin() + static_cast<long>(rates.size() / 2),
                     rates.end());
    return {rates[rates.size() / 2] * static_cast<double>(bytes), true};
}

void ModelCache::record_compile(std::size_t bytes, double seconds) const {
    const std::string path = folder_ + "/" + record_name;
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0) return; // the record only improves estimates
    char line[64];
    const int len = std::snprintf(line, sizeof line, "%zu\t%.3f\n", bytes, seconds);
    if (len > 0) (void)!::write(fd, line, static_cast<std::size_t>(len));
    ::close(fd);
}

} // namespace yamsc::analysis
