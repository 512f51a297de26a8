#include "analysis/fmu_toolchain.hpp"

#include "diag/errors.hpp"
#include "driver/derivation_loader.hpp"

#include <unistd.h>

namespace yamsc::analysis {

namespace {

/// CMake passes lists joined by '|' (its own separator, ';', splits definitions).
std::vector<std::string> split(const std::string& joined) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= joined.size()) {
        const std::size_t bar = joined.find('|', start);
        const std::string item =
            joined.substr(start, bar == std::string::npos ? std::string::npos : bar - start);
        if (!item.empty()) out.push_back(item);
        if (bar == std::string::npos) break;
        start = bar + 1;
    }
    return out;
}

struct Layout {
    std::vector<std::string> includes;
    std::string fmi, runtime, files; // the archives
    std::string exports;
    std::vector<std::string> aerodyn; // the blade elements' (FmuToolchain::aerodyn_archives)
};

Layout installed_under(const std::string& libdir, const std::string& includedir,
                       const std::string& datadir) {
    return {{includedir},
            libdir + "/libyamsc_fmi.a",
            libdir + "/libyamsc_runtime.a",
            libdir + "/libyamsc_files.a",
            datadir + "/yamsc/fmi/exports.map",
            {libdir + "/yamsc/fmu/libyamsc_aerodyn_input.a",
             libdir + "/yamsc/fmu/libyamsc_formats_aerodyn.a",
             libdir + "/yamsc/fmu/libyamsc_formats_elastodyn.a",
             libdir + "/yamsc/fmu/libyamsc_diag.a", libdir + "/yamsc/fmu/libyamsc_text.a"}};
}

Layout build_tree() {
    const std::vector<std::string> archives = split(YAMSC_FMU_ARCHIVES_BUILT);
    Layout l;
    l.includes = split(YAMSC_FMU_INCLUDES_BUILT);
    l.exports = YAMSC_FMU_EXPORTS_BUILT;
    l.aerodyn = split(YAMSC_FMU_AERODYN_ARCHIVES_BUILT);
    if (archives.size() == 3) {
        l.fmi = archives[0];
        l.runtime = archives[1];
        l.files = archives[2];
    }
    return l;
}

bool complete(const Layout& l) {
    for (const std::string& a : {l.fmi, l.runtime, l.files, l.exports})
        if (a.empty() || ::access(a.c_str(), R_OK) != 0) return false;
    return true;
}

} // namespace

FmuToolchain fmu_toolchain() {
    const std::string here = driver::own_folder();
    std::vector<Layout> candidates;
    if (!here.empty())
        candidates.push_back(installed_under(here + "/" + YAMSC_LIBDIR_FROM_BINDIR,
                                             here + "/" + YAMSC_INCLUDEDIR_FROM_BINDIR,
                                             here + "/" + YAMSC_DATADIR_FROM_BINDIR));
    const Layout installed = installed_under(YAMSC_LIBDIR_INSTALLED, YAMSC_INCLUDEDIR_INSTALLED,
                                             YAMSC_DATADIR_INSTALLED);
    const std::string tree = YAMSC_FMU_BUILD_TREE;
    const bool in_build_tree = here.compare(0, tree.size() + 1, tree + "/") == 0;
    candidates.push_back(in_build_tree ? build_tree() : installed);
    candidates.push_back(in_build_tree ? installed : build_tree());
    std::string tried;
    for (const Layout& l : candidates) {
        if (!complete(l)) {
            tried += "\n  " + (l.fmi.empty() ? std::string("(no build tree)") : l.fmi);
            continue;
        }
        FmuToolchain t;
        t.include_dirs = l.includes;
        for (const std::string& dir : split(YAMSC_FMU_SYSTEM_INCLUDES))
            t.include_dirs.push_back(dir);
        t.archives = {l.fmi};
        t.hidden_archives = {l.runtime, l.files};
        for (const std::string& a : l.aerodyn)
            if (::access(a.c_str(), R_OK) == 0) t.aerodyn_archives.push_back(a);
        if (t.aerodyn_archives.size() != l.aerodyn.size()) t.aerodyn_archives.clear();
        t.link_flags = split(YAMSC_FMU_LINK_FLAGS);
        t.exports = l.exports;
        return t;
    }
    throw diag::UserError("cannot find the FMI unit's runtime (libyamsc_fmi.a and "
                          "libyamsc_runtime.a) of this yamsc; tried:" +
                          tried);
}

} // namespace yamsc::analysis
