#include "analysis/mooring_files.hpp"

#include "text/ascii.hpp"

#include "analysis/moordyn_mooring.hpp"
#include "diag/read_text.hpp"

#include <array>
#include <string>

namespace yamsc::analysis {

namespace {

const std::array<MooringFormatInfo, 2> formats{{
    {MooringFormat::map, "MAP++", "LINE DICTIONARY", &read_map_mooring},
    {MooringFormat::moordyn, "MoorDyn", "LINE TYPES", &read_moordyn_mooring},
}};

} // namespace

std::optional<MooringFormat> mooring_format(std::string_view text) {
    // A section header is a line of dashes around its name.
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = text.substr(start, end - start);
        if (line.find("---") != std::string_view::npos) {
            const std::string u = text::ascii_upper(line);
            for (const MooringFormatInfo& f : formats)
                if (u.find(f.marker) != std::string::npos) return f.format;
        }
        start = end + 1;
    }
    return std::nullopt;
}

const MooringFormatInfo& mooring_format_info(MooringFormat format) {
    for (const MooringFormatInfo& f : formats)
        if (f.format == format) return f;
    return formats.front();
}

std::optional<std::vector<runtime::mooring::Line>>
read_mooring_file(const std::filesystem::path& file, const MooringEnvironment& environment,
                  diag::Diagnostics& diags) {
    const auto source = diag::read_text_file(file.string(), diags);
    if (!source) return std::nullopt;
    const std::optional<MooringFormat> format = mooring_format(source->text());
    if (!format) {
        diags.error(diag::Kind::InvalidValue, {source, 1, 1},
                    "not a mooring file: neither MAP++'s (a LINE DICTIONARY section) nor "
                    "MoorDyn's (a LINE TYPES section)");
        return std::nullopt;
    }
    return mooring_format_info(*format).read(file, environment, diags);
}

} // namespace yamsc::analysis
