#include "driver/outputs.hpp"

#include "driver/sid_values.hpp"
#include "driver/values.hpp"

#include <yamsc/output_target.hpp>

#include <sys/stat.h>

#include <filesystem>

namespace yamsc::driver {

namespace fs = std::filesystem;

namespace {

/// What makes two names the same file.
struct Identity {
    bool exists = false; ///< then `device` and `inode` count, else `place`
    dev_t device = 0;
    ino_t inode = 0;
    std::string place; ///< a name not created yet: its folder resolved, then the name
    bool character_device = false;

    bool operator==(const Identity& other) const {
        if (exists != other.exists) return false;
        return exists ? device == other.device && inode == other.inode : place == other.place;
    }
};

Identity identity_of(const std::string& path) {
    Identity id;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        id.exists = true;
        id.device = st.st_dev;
        id.inode = st.st_ino;
        id.character_device = S_ISCHR(st.st_mode);
        return id;
    }
    // A dangling link writes its final target: that is the place.
    const fs::path target(runtime::resolve_output(path).path);
    std::error_code error;
    const fs::path folder =
        fs::canonical(target.parent_path().empty() ? fs::path(".") : target.parent_path(), error);
    id.place = error ? fs::absolute(target).lexically_normal().string()
                     : (folder / target.filename()).string();
    return id;
}

std::string named(const NamedFile& f) {
    return f.role + " '" + f.path + "'";
}

} // namespace

void check_outputs(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs) {
    std::vector<std::pair<const NamedFile*, Identity>> written;
    for (const NamedFile& output : outputs) {
        if (output.path.empty()) continue;
        runtime::resolve_output(output.path); // a folder or a socket fails here, early
        const Identity id = identity_of(output.path);
        if (id.character_device) continue;
        for (const NamedFile& input : inputs)
            if (!input.path.empty() && identity_of(input.path) == id)
                throw UsageError(named(output) + " is " + named(input) +
                                 ": an output must not replace an input (nothing was written)");
        for (const auto& [other, other_id] : written)
            if (other_id == id)
                throw UsageError(named(*other) + " and " + named(output) +
                                 " are the same file (nothing was written)");
        written.emplace_back(&output, id);
    }
}

std::vector<NamedFile> data_files_of(const model::Model& m) {
    std::vector<NamedFile> files;
    for (const std::string& path : m.files_read) files.push_back({"the model's data file", path});
    return files;
}

std::vector<NamedFile> sid_files_of(const std::string& spec) {
    std::vector<NamedFile> files;
    for (const auto& [body, path] : sid_spec_items(spec))
        files.push_back({"the --sid file of body " + body, path});
    return files;
}

std::string make_rule(const std::vector<std::string>& targets,
                      const std::vector<std::string>& dependencies) {
    // Escaped as GCC escapes them and as make and Ninja read them: a space and
    // '#' behind a backslash, '$' doubled. A line break cannot be written in a depfile at all.
    auto escape = [](const std::string& s) {
        std::string out;
        for (char c : s) {
            if (c == '\n' || c == '\r')
                throw UsageError("--depfile: the path '" + s +
                                 "' has a line break, which a "
                                 "depfile cannot express");
            out += c == ' ' ? "\\ " : c == '#' ? "\\#" : c == '$' ? "$$" : std::string(1, c);
        }
        return out;
    };
    std::string rule;
    for (const std::string& t : targets) rule += (rule.empty() ? "" : " ") + escape(t);
    rule += ":";
    for (const std::string& d : dependencies) rule += " " + escape(d);
    return rule + "\n";
}

} // namespace yamsc::driver
