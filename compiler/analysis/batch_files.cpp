#include "analysis/batch_files.hpp"

#include "diag/errors.hpp"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <utility>

namespace yamsc::analysis {

std::string default_output_dir(const std::string& manifest) {
    const bool csv = manifest.size() > 4 && manifest.compare(manifest.size() - 4, 4, ".csv") == 0;
    return (csv ? manifest.substr(0, manifest.size() - 4) : manifest) + ".out";
}

void make_dirs(const std::string& path) {
    for (std::size_t pos = 1; pos <= path.size(); ++pos)
        if (pos == path.size() || path[pos] == '/')
            if (::mkdir(path.substr(0, pos).c_str(), 0755) != 0 && errno != EEXIST)
                throw diag::UserError("cannot create the folder '" + path.substr(0, pos) + "'");
}

void remove_leftovers(const std::string& dir, const std::vector<std::string>& ids) {
    const std::set<std::string> pending(ids.begin(), ids.end());
    for (const auto& [folder, suffix] :
         {std::pair<std::string, std::string>{dir, ".csv.tmp."}, {dir + "/.records", ".tmp."}}) {
        DIR* d = ::opendir(folder.c_str());
        if (!d) continue;
        std::vector<std::string> names;
        while (const dirent* e = ::readdir(d)) {
            const std::string name = e->d_name;
            const std::size_t at = name.find(suffix);
            if (at != std::string::npos && pending.count(name.substr(0, at)))
                names.push_back(folder + "/" + name);
        }
        ::closedir(d);
        for (const std::string& n : names) std::remove(n.c_str());
    }
}

void forget(const std::string& dir, const std::string& id) {
    std::remove((dir + "/" + id + ".csv").c_str());
    std::remove((dir + "/.records/" + id).c_str());
}

std::string real_path(const std::string& path) {
    char buf[PATH_MAX];
    return ::realpath(path.c_str(), buf) ? std::string(buf) : path;
}

std::string replaced_input(const std::string& real_dir, const std::string& id,
                           const std::set<std::string>& inputs) {
    const std::string result = real_dir + "/" + id + ".csv";
    return inputs.count(result) ? result : "";
}

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace yamsc::analysis
