#pragma once
// The folder of models compiled on the fly (analysis/jit.hpp) and what keys
// them: by content, never by how a path was typed. A key changes with the
// model's text and data, the routines compiled, the C++ compiler and yamsc
// itself; nothing else.
#include <cstddef>
#include <string>

namespace yamsc::analysis {

/// `configured` if given, else $YAMSC_CACHE_DIR, $XDG_CACHE_HOME/yamsc,
/// ~/.cache/yamsc, /tmp/yamsc-cache-<uid>.
std::string cache_folder(const std::string& configured);

/// The C++ compiler to use: `configured`, $YAMSC_CXX, $CXX, the compiler yamsc
/// was built with, c++.
std::string compiler_of(const std::string& configured);

/// The compiler as a key: its resolved path (PATH searched, links followed),
/// size and modification time; a compiler upgraded in place changes it, and
/// nothing is run to find out.
std::string compiler_identity(const std::string& compiler);

/// A file a build reads (an archive, a linker script) as a key: its resolved
/// path, size and modification time; "?" when it cannot be read. Unlike
/// compiler_identity, it does not ask for a program.
std::string file_identity(const std::string& path);

/// yamsc as a key: its version and the size and modification time of the
/// running executable, so a rebuilt yamsc never loads another build's models.
std::string program_identity();

/// The CPU that -march=native compiles for: its model and feature flags
/// (/proc/cpuinfo; empty where that cannot be read).
std::string cpu_identity();

struct CompileEstimate {
    double seconds = 0;
    bool measured_here = false; // from this cache's record, else a built-in rate
};

/// A folder of compiled models (created on first use) with the record of the
/// compiles made into it, from which it estimates the next one.
class ModelCache {
public:
    explicit ModelCache(std::string folder);

    const std::string& folder() const { return folder_; }
    /// Where the model of that name and key is (or will be) stored.
    std::string library_path(const std::string& model_name, const std::string& key) const;
    /// How long a compile of `bytes` of generated C++ usually takes here: the
    /// median rate of the last compiles recorded, else a built-in rate.
    CompileEstimate estimate(std::size_t bytes) const;
    /// Appends a compile to the record (one short line; concurrent runs are safe).
    void record_compile(std::size_t bytes, double seconds) const;

private:
    std::string folder_;
};

} // namespace yamsc::analysis
