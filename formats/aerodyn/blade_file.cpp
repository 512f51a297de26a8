#include "aerodyn/blade_file.hpp"

#include "aerodyn/lines.hpp"

#include <cmath>
#include <string>

namespace yamsc::aerodyn {

using diag::Kind;

namespace {

struct Column {
    const char* name;
    bool required;
    double BladeNodeRow::*value; // null for BlAFID (an integer)
    bool marine;                 // buoyancy or marine coefficient: warned when not zero
};

// ReadBladeInputs' AvailableChanNames and RequiredChanNames, in its order.
const Column columns[] = {
    {"BlSpn", true, &BladeNodeRow::span, false},
    {"BlCrvAC", true, &BladeNodeRow::curve_ac, false},
    {"BlSwpAC", true, &BladeNodeRow::sweep_ac, false},
    {"BlCrvAng", false, &BladeNodeRow::curve_angle, false},
    {"BlTwist", true, &BladeNodeRow::twist, false},
    {"BlChord", true, &BladeNodeRow::chord, false},
    {"BlAFID", true, nullptr, false},
    {"t_c", false, &BladeNodeRow::t_c, false},
    {"BlCb", false, &BladeNodeRow::cb, true},
    {"BlCenBn", false, &BladeNodeRow::cen_bn, true},
    {"BlCenBt", false, &BladeNodeRow::cen_bt, true},
    {"BlCpn", false, &BladeNodeRow::cpn, true},
    {"BlCpt", false, &BladeNodeRow::cpt, true},
    {"BlCan", false, &BladeNodeRow::can, true},
    {"BlCat", false, &BladeNodeRow::cat, true},
    {"BlCam", false, &BladeNodeRow::cam, true},
};
constexpr int column_count = sizeof columns / sizeof columns[0];

} // namespace

std::optional<BladeFile> read_blade_file(const std::shared_ptr<const diag::SourceFile>& file,
                                         diag::Diagnostics& diags) {
    const int errors = diags.error_count();
    Cursor c(logical_lines(file, nullptr, diags), file, diags);
    c.skip_header(2); // the banner and the title
    auto entry = c.expect("NumBlNds");
    if (!entry) return std::nullopt;
    auto rows = count(c, *entry, 2);
    if (!rows) return std::nullopt;
    const Line* header = c.next("the header of the blade table");
    if (!header) return std::nullopt;
    int index[column_count];
    for (int k = 0; k < column_count; ++k) {
        index[k] = -1;
        for (std::size_t j = 0; j < header->tokens.size(); ++j)
            if (elastodyn::same_key(header->tokens[j].text, columns[k].name)) {
                index[k] = static_cast<int>(j);
                break;
            }
        if (index[k] < 0 && columns[k].required) {
            diags.error(Kind::MissingProperty, header->at(),
                        std::string("the blade table has no column '") + columns[k].name + "'");
        }
    }
    if (diags.error_count() != errors) return std::nullopt;
    if (!c.next("the units row of the blade table")) return std::nullopt;
    int needed = 0;
    for (int k = 0; k < column_count; ++k) needed = std::max(needed, index[k] + 1);

    BladeFile out;
    out.file = file;
    out.has_curve_angle = index[3] >= 0;
    bool marine = false;
    for (int r = 0; r < *rows; ++r) {
        const Line* line = c.next("row " + std::to_string(r + 1) + " of " + std::to_string(*rows) +
                                  " of the blade table (NumBlNds)");
        if (!line) return std::nullopt;
        if (static_cast<int>(line->tokens.size()) < needed) {
            diags.error(Kind::InvalidValue, line->at(),
                        "this row of the blade table has " + std::to_string(line->tokens.size()) +
                            " values, expected " + std::to_string(needed));
            return std::nullopt;
        }
        BladeNodeRow row;
        row.at = line->at();
        for (int k = 0; k < column_count; ++k) {
            if (index[k] < 0) continue;
            const auto& token = line->tokens[static_cast<std::size_t>(index[k])];
            const diag::Location at = line->at(index[k]);
            const auto v = elastodyn::parse_number(token.text);
            if (!v) {
                diags.error(Kind::InvalidValue, at,
                            "'" + token.text + "' in column '" + columns[k].name +
                                "' is not a number");
                continue;
            }
            if (!columns[k].value) {
                row.airfoil_id_at = at;
                if (*v != std::floor(*v) || *v < 1 || *v > max_count)
                    diags.error(Kind::InvalidValue, at,
                                "BlAFID must be a positive integer (an airfoil of the AeroDyn "
                                "file's AFNames), not '" +
                                    token.text + "'");
                else
                    row.airfoil_id = static_cast<int>(*v);
                continue;
            }
            row.*(columns[k].value) = *v;
            if (columns[k].marine && *v != 0 && !marine) {
                marine = true;
                diags.warning(Kind::NotSupported, at,
                              std::string(columns[k].name) +
                                  " is not zero: buoyancy and marine (MHK) loads are not "
                                  "converted");
            }
        }
        if (r == 0 && row.span != 0)
            diags.error(Kind::InvalidValue, line->at(index[0]),
                        "BlSpn of the first node must be 0 (the blade root)");
        if (r > 0 && !(row.span > out.nodes.back().span))
            diags.error(Kind::InvalidValue, line->at(index[0]),
                        "BlSpn must rise from node to node");
        if (!(row.chord > 0))
            diags.error(Kind::InvalidValue, line->at(index[5]), "BlChord must be positive");
        out.nodes.push_back(row);
    }
    if (diags.error_count() != errors) return std::nullopt;
    return out;
}

} // namespace yamsc::aerodyn
