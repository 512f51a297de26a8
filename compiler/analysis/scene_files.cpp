#include "analysis/scene_files.hpp"

#include "diag/errors.hpp"
#include "driver/outputs.hpp"

#include <yamsc/atomic_file.hpp>

#include <cerrno>
#include <cstring>
#include <sys/stat.h>

namespace yamsc::analysis {

namespace {

std::string joined(const std::string& dir, const std::string& name) {
    return dir.empty() || dir.back() == '/' ? dir + name : dir + "/" + name;
}

void make_folder(const std::string& dir) {
    struct stat st {};
    if (::stat(dir.c_str(), &st) == 0) {
        if (!S_ISDIR(st.st_mode))
            throw diag::UsageError("--vtk " + dir + ": exists and is not a folder");
        return;
    }
    if (::mkdir(dir.c_str(), 0777) != 0)
        throw diag::UserError("--vtk " + dir + ": cannot make the folder: " + std::strerror(errno));
}

/// A file of the run may be replaced only if it is a regular file: a link or a
/// device in the folder is left alone.
void refuse_unless_regular(const std::string& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw diag::UsageError("--vtk: '" + path +
                               "' exists and is not a regular file (a link, a device or a "
                               "folder); the run's files replace only files");
}

} // namespace

void check_scene_folder(const std::string& dir) {
    struct stat st {};
    if (::stat(dir.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
        throw diag::UsageError("--vtk " + dir + ": exists and is not a folder");
}

void write_scene_folder(const std::string& dir, const std::string& model, const Scene& scene,
                        const runtime::SimulationResult& with_scene, const SimRun& run,
                        driver::Channels channels, const std::vector<driver::NamedFile>& inputs) {
    std::vector<std::pair<std::string, std::string>> files;
    std::vector<vtk::Entry> entries;
    for (std::size_t row = 0; row < with_scene.rows(); ++row) {
        const std::string name = vtk::vtp_name(model, row);
        files.emplace_back(joined(dir, name),
                           vtk::write_vtp(scene.topology(), scene.points(with_scene, row)));
        entries.push_back({with_scene.time[row], name});
    }
    files.emplace_back(joined(dir, vtk::pvd_name(model)), vtk::write_pvd(entries));
    const std::string csv = joined(dir, vtk::csv_name(model));
    std::vector<driver::NamedFile> outputs;
    for (const auto& f : files) outputs.push_back({"--vtk", f.first});
    outputs.push_back({"--vtk", csv});
    make_folder(dir);
    for (const driver::NamedFile& f : outputs) refuse_unless_regular(f.path);
    driver::check_outputs(inputs, outputs);
    runtime::write_files_atomically(files);
    write_sim_csv(run, channels, csv);
}

} // namespace yamsc::analysis
