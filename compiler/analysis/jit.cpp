#include "analysis/jit.hpp"

#include "codegen/emit.hpp"
#include "codegen/module.hpp"
#include "driver/files.hpp"

#include "embedded_abi.hpp"
#include <yamsc/atomic_file.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace yamsc::driver {

namespace {

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

std::string cache_folder(const JitOptions& o) {
    if (!o.cache_dir.empty()) return o.cache_dir;
    if (auto d = env("YAMSC_CACHE_DIR"); !d.empty()) return d;
    if (auto d = env("XDG_CACHE_HOME"); !d.empty()) return d + "/yamsc";
    if (auto d = env("HOME"); !d.empty()) return d + "/.cache/yamsc";
    return "/tmp/yamsc-cache-" + std::to_string(::getuid());
}

void make_dirs(const std::string& path) {
    for (std::size_t pos = 1; pos <= path.size(); ++pos) {
        if (pos == path.size() || path[pos] == '/') {
            std::string part = path.substr(0, pos);
            if (::mkdir(part.c_str(), 0755) != 0 && errno != EEXIST)
                throw std::runtime_error("cannot create the cache folder '" + part + "'");
        }
    }
}

std::string compiler_of(const JitOptions& o) {
    if (!o.compiler.empty()) return o.compiler;
    if (auto c = env("YAMSC_CXX"); !c.empty()) return c;
    if (auto c = env("CXX"); !c.empty()) return c;
#ifdef YAMSC_CXX_COMPILER
    if (std::string c = YAMSC_CXX_COMPILER; !c.empty() && ::access(c.c_str(), X_OK) == 0) return c;
#endif
    return "c++";
}

bool exists(const std::string& path) {
    return ::access(path.c_str(), R_OK) == 0;
}

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

} // namespace

std::string shared_model_source(const ir::System& eq) {
    codegen::Module module = codegen::build_module(eq);
    codegen::EmitOptions options;
    options.compiler_version = YAMSC_VERSION;
    options.command_line = "yamsc sim (compiled on the fly)";
    std::string source = codegen::emit_cpp(module, options).source;
    return source + "\n// ---- C ABI for the runtime's loader ----\n" + abi_export_text + "\n" +
           "YAMSC_EXPORT_MODEL(" + eq.model_name + ")\n";
}

std::unique_ptr<runtime::SharedModel> load_compiled_model(const ir::System& eq,
                                                          const JitOptions& o) {
    auto say = [&](const std::string& s) {
        if (o.progress) o.progress(s);
    };
    const std::string source = shared_model_source(eq);
    const std::string compiler = compiler_of(o);
    const std::string flags = "-std=c++17 -O2 -shared -fPIC -fvisibility=hidden";
    const std::string key = digest(source + "\n" + compiler + "\n" + flags);
    const std::string dir = cache_folder(o);
    make_dirs(dir);
    const std::string base = dir + "/" + eq.model_name + "-" + key;
    const std::string library = base + ".so";
    if (!exists(library)) {
        say("compiling the generated model with " + compiler + " (cached in " + dir + ")");
        const std::string tmp = base + ".tmp." + std::to_string(::getpid());
        runtime::write_file_atomically(tmp + ".cpp", source);
        const std::string log = tmp + ".log";
        std::string cmd = shell_quote(compiler) + " " + flags + " -o " + shell_quote(tmp + ".so") +
                          " " + shell_quote(tmp + ".cpp") + " > " + shell_quote(log) + " 2>&1";
        int status = std::system(cmd.c_str());
        std::remove((tmp + ".cpp").c_str());
        if (status != 0) {
            std::ifstream in(log);
            std::stringstream messages;
            messages << in.rdbuf();
            std::remove(log.c_str());
            std::remove((tmp + ".so").c_str());
            throw std::runtime_error("the C++ compiler failed on the generated model (" + compiler +
                                     "):\n" + messages.str().substr(0, 4000));
        }
        std::remove(log.c_str());
        if (std::rename((tmp + ".so").c_str(), library.c_str()) != 0) {
            std::remove((tmp + ".so").c_str());
            throw std::runtime_error("cannot store the compiled model in '" + library + "'");
        }
    } else {
        say("using the compiled model cached in " + library);
    }
    return std::make_unique<runtime::SharedModel>(library);
}

} // namespace yamsc::driver
