#include "analysis/fmu_binary.hpp"

#include "analysis/compiler_invocation.hpp"
#include "analysis/fmu_toolchain.hpp"
#include "analysis/jit_cache.hpp"
#include "diag/errors.hpp"
#include "driver/files.hpp"
#include "text/number.hpp"

#include <yamsc/atomic_file.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace yamsc::analysis {

namespace {

namespace fs = std::filesystem;

// As the JIT compiles models (jit.cpp: -ffp-contract=off keeps the numbers of a
// plain build to the last bit, so the unit's steps equal `yamsc sim`'s), but
// without -march=native: a unit is meant to run on other machines.
const std::vector<std::string> cxx_flags{"-std=c++17", "-O2", "-ffp-contract=off", "-fPIC",
                                         "-fvisibility=hidden"};

/// A private folder for the build's files, removed with this object.
class BuildFolder {
public:
    BuildFolder() {
        std::string pattern = (fs::temp_directory_path() / "yamsc-fmu-XXXXXX").string();
        if (!::mkdtemp(pattern.data()))
            throw diag::UserError("cannot create a temporary folder for the unit's build");
        path_ = pattern;
    }
    ~BuildFolder() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    BuildFolder(const BuildFolder&) = delete;
    BuildFolder& operator=(const BuildFolder&) = delete;
    std::string write(const std::string& name, const std::string& text) const {
        const std::string path = path_ + "/" + name;
        runtime::write_file_atomically(path, text);
        return path;
    }
    std::string path(const std::string& name) const { return path_ + "/" + name; }

private:
    std::string path_;
};

std::string list(const std::vector<double>& values) {
    std::string s = "{";
    for (double v : values) s += (s.size() > 1 ? ", " : "") + text::shortest(v);
    return s + "}";
}

std::string base_name(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string folder_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

bool is_c_source(const std::string& path) {
    return path.size() > 2 && path.compare(path.size() - 2, 2, ".c") == 0;
}

} // namespace

std::string file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw diag::UserError("cannot read '" + path + "'");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string glue_source(const UnitSettings& s) {
    const char* method = s.method == runtime::Method::cvode  ? "cvode"
                         : s.method == runtime::Method::abm4 ? "abm4"
                                                             : "rk4";
    std::vector<double> state = s.q0;
    state.insert(state.end(), s.qd0.begin(), s.qd0.end());
    return "// The FMI unit of the model in model.hpp (written by yamsc fmu).\n"
           "#include \"model.hpp\"\n"
           "#include <yamsc/fmi/blade_elements.hpp>\n"
           "#include <yamsc/fmi/blocks.hpp>\n"
           "#include <yamsc/fmi/unit.hpp>\n"
           "namespace {\n"
           "::yamsc::fmi::UnitSettings yamsc_unit_settings() {\n"
           "    ::yamsc::fmi::UnitSettings s;\n"
           "    s.token = \"" +
           s.token +
           "\";\n"
           "    s.method = ::yamsc::runtime::Method::" +
           method +
           ";\n"
           "    s.step = " +
           text::shortest(s.step) +
           ";\n"
           "    s.initial_state = " +
           list(state) + ";\n" + s.blocks +
           "    return s;\n"
           "}\n"
           "} // namespace\n"
           "YAMSC_FMI_UNIT_WITH(" +
           s.model_namespace + "::Model, yamsc_unit_settings())\n";
}

std::string build_unit_binary(const UnitSources& sources, const std::string& compiler,
                              const std::function<void(const std::string&)>& progress) {
    FmuToolchain tools = fmu_toolchain();
    if (sources.blade_elements) {
        if (tools.aerodyn_archives.empty())
            throw diag::UserError("yamsc fmu: this yamsc has no AeroDyn reader to link into a "
                                  "unit with blade elements (libyamsc_aerodyn_input.a and the "
                                  "libraries it needs, installed under lib/yamsc/fmu/)");
        // Before the runtime's: the reader calls it.
        tools.hidden_archives.insert(tools.hidden_archives.begin(), tools.aerodyn_archives.begin(),
                                     tools.aerodyn_archives.end());
    }
    // Cached by content, as the JIT's libraries (jit_cache.hpp): the FMI 3.0 and
    // 2.0 units of a model share their binary, and a rebuild repackages at once.
    std::string key = sources.model.source + sources.model.header + sources.glue +
                      sources.external_prototypes + compiler_identity(compiler) + "\n" +
                      joined_words(cxx_flags) + "\n" + joined_words(tools.link_flags);
    if (!sources.external.empty()) key += file_bytes(sources.external);
    // The archives are the unit's runtime: a rebuilt one is another unit.
    for (const std::vector<std::string>* files : {&tools.archives, &tools.hidden_archives})
        for (const std::string& a : *files) key += "\n" + file_identity(a);
    key += "\n" + file_identity(tools.exports);
    const std::string library =
        ModelCache(cache_folder("")).library_path("fmu_unit", driver::digest(key));
    if (::access(library.c_str(), R_OK) == 0) {
        if (progress) progress("using the unit's binary cached in " + library);
        return file_bytes(library);
    }
    const BuildFolder folder;
    folder.write("model.hpp", sources.model.header);
    std::vector<std::string> arguments = cxx_flags;
    arguments.push_back("-shared");
    for (const std::string& dir : tools.include_dirs) arguments.push_back("-I" + dir);
    arguments.push_back(folder.write("model.cpp", sources.model.source));
    arguments.push_back(folder.write("glue.cpp", sources.glue));
    if (!sources.external.empty()) {
        // Compiled on its own (its language may be C) against the prototypes.
        const std::string object = folder.path("external.o");
        LibraryBuild build(object);
        const bool c = is_c_source(sources.external);
        std::vector<std::string> external{"-c",
                                          "-x",
                                          c ? "c" : "c++",
                                          "-O2",
                                          "-fPIC",
                                          "-fvisibility=hidden",
                                          "-include",
                                          folder.write("prototypes.h", sources.external_prototypes),
                                          "-I" + folder_of(sources.external),
                                          sources.external};
        if (!c) external.insert(external.begin() + 3, "-std=c++17");
        if (progress) progress("compiling the external functions of " + sources.external);
        try {
            build.compile(compiler, external);
        } catch (const CompilerFailed& e) {
            throw diag::UserError("--external " + sources.external +
                                  " does not compile against the model's prototypes (" + compiler +
                                  "):\n" + e.messages + "the prototypes are:\n" +
                                  sources.external_prototypes);
        }
        arguments.push_back(object);
    }
    arguments.push_back("-Wl,--whole-archive");
    for (const std::string& a : tools.archives) arguments.push_back(a);
    arguments.push_back("-Wl,--no-whole-archive");
    std::string hidden = "-Wl,--exclude-libs,";
    for (const std::string& a : tools.hidden_archives) {
        arguments.push_back(a);
        hidden += (hidden.back() == ',' ? "" : ":") + base_name(a);
    }
    arguments.push_back(hidden);
    for (const std::string& f : tools.link_flags) arguments.push_back(f);
    arguments.push_back("-Wl,--no-undefined");
    arguments.push_back("-Wl,--version-script=" + tools.exports);
    if (progress) progress("compiling the unit with " + compiler);
    try {
        LibraryBuild(library).compile(compiler, arguments);
    } catch (const CompilerFailed& e) {
        throw diag::UserError("the C++ compiler failed on the unit (" + compiler + "):\n" +
                              e.messages);
    }
    return file_bytes(library);
}

} // namespace yamsc::analysis
