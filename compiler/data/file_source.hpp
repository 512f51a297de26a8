#pragma once
// The data stage: the files a model names (SID, ElastoDyn tower and blade
// files), read with located errors and size limits, and the beam preprocessor
// (beam/) run on them. It implements the checker's model::DataSource and keeps
// the list of files it read, for the source digest and the depfile.
#include "model/checker.hpp"
#include "model/data_source.hpp"

#include <string>
#include <vector>

namespace yamsc::data {

class FileSource final : public model::DataSource {
public:
    /// `base_dir`: where relative names start (the model's folder, with a trailing
    /// slash, or empty for the working directory).
    explicit FileSource(std::string base_dir) : base_dir_(std::move(base_dir)) {}

    std::optional<sid::Sid> sid_file(const std::string& name, const diag::Location& at,
                                     diag::Diagnostics& diags) override;
    std::optional<beam::Beam> beam_file(const std::string& format, const std::string& name,
                                        double length, const std::vector<std::string>& modes,
                                        const diag::Location& at,
                                        diag::Diagnostics& diags) override;
    std::optional<sid::Sid> beam_sid(const beam::Beam& beam, const std::string& body,
                                     const diag::Location& at, diag::Diagnostics& diags) override;
    std::optional<sid::Sid> section_sid(const beam::Beam& beam, int node, const diag::Location& at,
                                        diag::Diagnostics& diags) override;

    /// The paths of the files read so far, in reading order.
    const std::vector<std::string>& files_read() const { return files_read_; }

private:
    std::shared_ptr<const diag::SourceFile> read(const std::string& name, const diag::Location& at,
                                                 diag::Diagnostics& diags);

    std::string base_dir_;
    std::vector<std::string> files_read_;
};

/// The folder of a model file, as FileSource's base: "dir/" for "dir/m.mbd", "".
std::string folder_of(const std::string& model_path);

/// model::check with the data of the files the model names, relative to the
/// model's own folder; the checked model lists them in `files_read`.
std::optional<model::Model> check_model(const ast::ModelFile& file, diag::Diagnostics& diags);

} // namespace yamsc::data
