#include "analysis/compiler_invocation.hpp"

#include <yamsc/atomic_file.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace yamsc::analysis {
namespace {

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string read_and_remove(const std::string& path) {
    std::stringstream text;
    {
        std::ifstream in(path);
        text << in.rdbuf();
    }
    std::remove(path.c_str());
    return text.str();
}

} // namespace

CompilerFailed::CompilerFailed(const std::string& compiler, std::string messages)
    : std::runtime_error("the C++ compiler (" + compiler + ") failed:\n" + messages),
      compiler(compiler), messages(std::move(messages)) {}

LibraryBuild::LibraryBuild(std::string library)
    : library_(std::move(library)), stem_(library_ + ".tmp." + std::to_string(::getpid())) {}

LibraryBuild::~LibraryBuild() {
    for (const std::string& path : temporaries_) std::remove(path.c_str());
}

std::string LibraryBuild::temporary(const std::string& suffix, const std::string& text) {
    const std::string path = stem_ + suffix;
    temporaries_.push_back(path);
    runtime::write_file_atomically(path, text);
    return path;
}

void LibraryBuild::compile(const std::string& compiler, const std::vector<std::string>& arguments) {
    const std::string output = stem_ + ".so", log = stem_ + ".log";
    temporaries_.push_back(output);
    std::string command = shell_quote(compiler);
    for (const std::string& a : arguments) command += " " + shell_quote(a);
    command += " -o " + shell_quote(output) + " > " + shell_quote(log) + " 2>&1";
    const int status = std::system(command.c_str());
    const std::string messages = read_and_remove(log);
    if (status != 0) throw CompilerFailed(compiler, messages.substr(0, 4000));
    if (std::rename(output.c_str(), library_.c_str()) != 0)
        throw std::runtime_error("cannot store the compiled library in '" + library_ + "'");
}

std::string joined_words(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
    return out;
}

} // namespace yamsc::analysis
