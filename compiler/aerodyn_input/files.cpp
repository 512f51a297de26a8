#include "aerodyn/airfoil_file.hpp"
#include "aerodyn_input/rotor.hpp"
#include "diag/read_text.hpp"

#include <algorithm>

namespace yamsc::aerodyn_input {

std::vector<std::string> aerodyn_files(const std::filesystem::path& primary, int num_blades,
                                       diag::Diagnostics& diags) {
    std::vector<std::string> files;
    auto add = [&files](const std::string& path) {
        if (std::find(files.begin(), files.end(), path) == files.end()) files.push_back(path);
    };
    const aerodyn::IncludeReader recording =
        [&add](const std::string& path, const diag::Location& at, diag::Diagnostics& d) {
            add(path);
            return diag::read_text_file(path, d, at);
        };
    add(primary.string());
    auto source = diag::read_text_file(primary.string(), diags);
    if (!source) return {};
    auto p = aerodyn::read_primary_file(source, num_blades, diags, recording);
    if (!p) return {};
    const std::size_t blades =
        std::min(p->blade_files.size(), static_cast<std::size_t>(num_blades));
    for (std::size_t k = 0; k < blades; ++k) add(p->blade_files[k].path);
    aerodyn::AirfoilColumns columns;
    columns.alpha = p->in_col_alfa;
    columns.cl = p->in_col_cl;
    columns.cd = p->in_col_cd;
    columns.cm = p->in_col_cm;
    columns.cpmin = p->in_col_cpmin;
    for (const aerodyn::FileName& name : p->airfoils) {
        add(name.path);
        if (auto airfoil = diag::read_text_file(name.path, diags, name.at))
            aerodyn::read_airfoil_file(airfoil, columns, diags, recording);
    }
    if (diags.has_errors()) return {};
    return files;
}

} // namespace yamsc::aerodyn_input
