#pragma once
// The one place that runs the C++ compiler: the JIT's model libraries
// (jit.hpp) and the user's external functions (external_library.hpp) are
// both shared libraries built by `COMPILER ARGUMENTS -o LIBRARY`, with the
// compiler's messages captured, into a cache where a half-written library
// must never appear.
#include <stdexcept>
#include <string>
#include <vector>

namespace yamsc::analysis {

/// The compiler failed: `messages` is what it printed (stdout and stderr, at
/// most 4000 characters); what() names the compiler and gives them.
class CompilerFailed : public std::runtime_error {
public:
    CompilerFailed(const std::string& compiler, std::string messages);
    std::string compiler, messages;
};

/// A shared library being built into `library`: the temporary files it needs
/// (a generated source, prototypes) are written beside it, named after it and
/// this process, and removed with this object; the library appears under its
/// name only complete (a temporary renamed).
class LibraryBuild {
public:
    explicit LibraryBuild(std::string library);
    ~LibraryBuild();
    LibraryBuild(const LibraryBuild&) = delete;
    LibraryBuild& operator=(const LibraryBuild&) = delete;

    /// Writes `text` to a temporary file ending in `suffix` (".cpp", ".h"); its path.
    std::string temporary(const std::string& suffix, const std::string& text);

    /// Runs `compiler ARGUMENTS -o LIBRARY` (each argument one word, the
    /// inherited environment, stdout and stderr captured). Throws
    /// CompilerFailed when it fails, std::runtime_error when the library
    /// cannot be stored.
    void compile(const std::string& compiler, const std::vector<std::string>& arguments);

private:
    std::string library_, stem_;
    std::vector<std::string> temporaries_;
};

/// `words` joined by spaces (flags in a cache key).
std::string joined_words(const std::vector<std::string>& words);

} // namespace yamsc::analysis
