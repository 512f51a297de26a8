#pragma once
// The mooring input files `load mooring` takes (`--mooring FILE`): MAP++'s and
// MoorDyn's line definitions, both as the runtime's quasi-static lines. One row
// per format: what marks its file and its reader; a new format is a row.
#include "analysis/map_mooring.hpp"
#include "diag/diagnostics.hpp"
#include "yamsc/mooring/mooring_system.hpp"

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

namespace yamsc::analysis {

enum class MooringFormat { map, moordyn };

struct MooringFormatInfo {
    MooringFormat format;
    std::string_view name;   // for messages: "MAP++", "MoorDyn"
    std::string_view marker; // a section header only its files have
    std::optional<std::vector<runtime::mooring::Line>> (*read)(const std::filesystem::path&,
                                                               const MooringEnvironment&,
                                                               diag::Diagnostics&);
};

/// The format of a mooring file, from its section headers (MAP++'s LINE
/// DICTIONARY, MoorDyn's LINE TYPES); nullopt when neither is there.
std::optional<MooringFormat> mooring_format(std::string_view text);

const MooringFormatInfo& mooring_format_info(MooringFormat format);

/// Reads either kind of file as the runtime's lines; an error names both
/// formats when the file is neither.
std::optional<std::vector<runtime::mooring::Line>>
read_mooring_file(const std::filesystem::path& file, const MooringEnvironment& environment,
                  diag::Diagnostics& diags);

} // namespace yamsc::analysis
