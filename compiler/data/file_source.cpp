#include "data/file_source.hpp"

#include "beam/elastodyn.hpp"
#include "beam/make_sid.hpp"
#include "diag/read_text.hpp"
#include "sid/reader.hpp"

namespace yamsc::data {

std::shared_ptr<const diag::SourceFile>
FileSource::read(const std::string& name, const diag::Location& at, diag::Diagnostics& diags) {
    const std::string path = !name.empty() && name[0] == '/' ? name : base_dir_ + name;
    auto file = diag::read_text_file(path, diags, at);
    if (file) files_read_.push_back(path);
    return file;
}

std::optional<sid::Sid> FileSource::sid_file(const std::string& name, const diag::Location& at,
                                             diag::Diagnostics& diags) {
    auto file = read(name, at, diags);
    if (!file) return std::nullopt;
    const int errors = diags.error_count();
    auto data = sid::read_sid(file, diags);
    if (diags.error_count() > errors) return std::nullopt;
    return data;
}

std::optional<beam::Beam> FileSource::beam_file(const std::string& format, const std::string& name,
                                                double length,
                                                const std::vector<std::string>& modes,
                                                const diag::Location& at,
                                                diag::Diagnostics& diags) {
    if (format != "elastodyn_tower" && format != "elastodyn_blade") {
        diags.error(diag::Kind::InvalidValue, at,
                    "unknown beam file format '" + format + "'" +
                        diag::did_you_mean(format, {"elastodyn_tower", "elastodyn_blade"}) +
                        " (known: elastodyn_tower, elastodyn_blade)");
        return std::nullopt;
    }
    auto file = read(name, at, diags);
    if (!file) return std::nullopt;
    const int errors = diags.error_count();
    auto beam = format == "elastodyn_tower"
                    ? beam::read_elastodyn_tower(file, length, modes, diags)
                    : beam::read_elastodyn_blade(file, length, modes, diags);
    if (diags.error_count() > errors) return std::nullopt;
    return beam;
}

std::optional<sid::Sid> FileSource::beam_sid(const beam::Beam& beam, const std::string& body,
                                             const diag::Location& at, diag::Diagnostics& diags) {
    if (auto problem = beam::check_beam(beam)) {
        diags.error(diag::Kind::InvalidValue, at,
                    "the beam of '" + body + "' is not valid: " + *problem);
        return std::nullopt;
    }
    return beam::make_sid(beam);
}

std::optional<sid::Sid> FileSource::section_sid(const beam::Beam& beam, int node,
                                                const diag::Location& at,
                                                diag::Diagnostics& diags) {
    (void)at;
    (void)diags;
    return beam::make_section_sid(beam, node); // the beam passed beam_sid()
}

std::string folder_of(const std::string& model_path) {
    const auto slash = model_path.rfind('/');
    return slash == std::string::npos ? std::string() : model_path.substr(0, slash + 1);
}

std::optional<model::Model> check_model(const ast::ModelFile& file, diag::Diagnostics& diags) {
    FileSource data(file.source ? folder_of(file.source->path()) : std::string());
    auto checked = model::check(file, data, diags);
    if (checked) checked->files_read = data.files_read();
    return checked;
}

} // namespace yamsc::data
