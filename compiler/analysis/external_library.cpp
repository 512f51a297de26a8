#include "analysis/external_library.hpp"

#include "analysis/compiler_invocation.hpp"
#include "analysis/jit_cache.hpp"
#include "diag/errors.hpp"
#include "driver/files.hpp"
#include "driver/pipeline.hpp"

#include <dlfcn.h>
#include <fstream>
#include <optional>
#include <sstream>
#include <unistd.h>

namespace yamsc::analysis {

using driver::digest;
using driver::external_prototypes;
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

/// The language of a source, or "" for a library.
std::string source_language(const std::string& spec) {
    if (ends_with(spec, ".c")) return "c";
    for (const char* ext : {".cpp", ".cc", ".cxx", ".C"})
        if (ends_with(spec, ext)) return "c++";
    return "";
}

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw diag::UserError("--external: cannot read '" + path + "'");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string folder_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

const std::vector<std::string> flags{"-O2", "-shared", "-fPIC"};

/// The user's source compiled against the prototypes, from the cache when it is there.
std::string compiled_source(const model::Model& m, const std::string& spec,
                            const std::string& language, const JitOptions& o) {
    const std::string source = read_all(spec);
    const std::string prototypes = external_prototypes(m);
    const std::string compiler = compiler_of(o.compiler);
    const ModelCache cache(cache_folder(o.cache_dir));
    const std::string key = digest(language + "\n" + source + "\n" + prototypes + "\n" +
                                   joined_words(flags) + "\n" + compiler_identity(compiler));
    const std::string library = cache.library_path(m.name + "_external", key);
    if (::access(library.c_str(), R_OK) == 0) {
        if (o.progress) o.progress("using the external functions cached in " + library);
        return library;
    }
    if (o.notice) o.notice("compiling the external functions of " + spec + " with " + compiler);
    LibraryBuild build(library);
    std::vector<std::string> arguments{"-x", language};
    if (language == "c++") arguments.emplace_back("-std=c++17");
    arguments.insert(arguments.end(), flags.begin(), flags.end());
    arguments.insert(arguments.end(),
                     {"-include", build.temporary(".h", prototypes), "-I" + folder_of(spec), spec});
    try {
        build.compile(compiler, arguments);
    } catch (const CompilerFailed& e) {
        throw diag::UserError("--external " + spec +
                              " does not compile against the model's prototypes (" + compiler +
                              "):\n" + e.messages + "the prototypes are:\n" + prototypes);
    } catch (const std::runtime_error& e) {
        throw diag::UserError(e.what());
    }
    return library;
}

} // namespace

std::optional<ExternalLibrary> load_external_library(const model::Model& m, const std::string& spec,
                                                     const JitOptions& o,
                                                     diag::Diagnostics& diags) {
    if (m.externals.empty()) {
        if (spec.empty()) return ExternalLibrary{};
        throw diag::UsageError("--external " + spec + ": the model declares no external function");
    }
    if (spec.empty()) {
        for (const model::External& e : m.externals)
            diags.error(diag::Kind::Io, e.loc,
                        "external function '" + e.name +
                            "' has no implementation: give --external lib.so (a library "
                            "exporting it) or --external file.c (its source)");
        return std::nullopt;
    }
    ExternalLibrary lib;
    const std::string language = source_language(spec);
    lib.path = language.empty() ? spec : compiled_source(m, spec, language, o);
    // A name without a slash would be searched on the library path instead.
    const std::string open_path =
        lib.path.find('/') == std::string::npos ? "./" + lib.path : lib.path;
    // Never closed: the model's library binds to it and lives as long as its views.
    void* handle = ::dlopen(open_path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!handle) {
        const char* why = ::dlerror();
        throw diag::UserError("--external: cannot load '" + lib.path +
                              "': " + (why ? why : "unknown reason"));
    }
    bool ok = true;
    for (const model::External& e : m.externals) {
        ::dlerror();
        if (!::dlsym(handle, e.name.c_str())) {
            diags.error(diag::Kind::UnknownName, e.loc,
                        "external function '" + e.name + "' is not in " + spec + " (no symbol '" +
                            e.name + "': is it declared extern \"C\" and exported?)");
            ok = false;
            continue;
        }
        // The model's library binds to the first definition in the global scope:
        // one in the program or a library loaded before (libc's `send`) would win.
        void* mine = ::dlsym(handle, e.name.c_str());
        void* first = ::dlsym(RTLD_DEFAULT, e.name.c_str());
        if (first != mine) {
            Dl_info info{};
            const bool known = ::dladdr(first, &info) != 0 && info.dli_fname;
            diags.error(diag::Kind::DuplicateName, e.loc,
                        "external function '" + e.name + "' is also a symbol of " +
                            (known ? std::string(info.dli_fname) : std::string("the program")) +
                            ", which would be called instead: rename it (e.g. with the model's "
                            "name as a prefix)");
            ok = false;
            continue;
        }
        if (e.without_jacobian)
            lib.notes.push_back(e.name + ": derivatives by central differences (without jacobian)");
        else if (!::dlsym(handle, (e.name + "_jacobian").c_str()))
            lib.notes.push_back(e.name + ": derivatives by central differences (no " + e.name +
                                "_jacobian in " + spec + ")");
        else
            lib.notes.push_back(e.name + ": derivatives from " + e.name + "_jacobian");
    }
    if (!ok) return std::nullopt;
    return lib;
}

} // namespace yamsc::analysis
