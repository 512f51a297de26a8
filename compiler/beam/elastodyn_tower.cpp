// The ElastoDyn tower file (OpenFAST ElastoDyn "TWR" input): distributed properties
// per height fraction and polynomial fore-aft / side-side mode shapes.
#include "beam/elastodyn.hpp"
#include "beam/elastodyn_beam.hpp"

namespace yamsc::beam {

const std::vector<std::string>& elastodyn_tower_modes() {
    static const std::vector<std::string> names{"fa1", "fa2", "ss1", "ss2"};
    return names;
}

std::optional<Beam> read_elastodyn_tower(const std::shared_ptr<const diag::SourceFile>& file,
                                         double length, const std::vector<std::string>& modes,
                                         diag::Diagnostics& diags) {
    const ElastoDynFile f(file);
    const int errors = diags.error_count();
    Beam beam;
    beam.length = length;
    beam.integrated_shapes = false; // ElastoDyn's tower: SHP at its elements
    check_ed_length(f, length, diags);
    // Fore-aft bending displaces the tower along x (resisted by EI_y), side-side along y.
    const std::vector<EdModeKeys> known{{"fa1", "TwFAM1Sh", "TwrFADmp(1)", "FAStTunr(1)", 0},
                                        {"fa2", "TwFAM2Sh", "TwrFADmp(2)", "FAStTunr(2)", 0},
                                        {"ss1", "TwSSM1Sh", "TwrSSDmp(1)", "SSStTunr(1)", 1},
                                        {"ss2", "TwSSM2Sh", "TwrSSDmp(2)", "SSStTunr(2)", 1}};
    read_ed_modes(f, modes, known, beam, diags);
    auto mass_factor = f.get_double("AdjTwMa", diags);
    auto fa_factor = f.get_double("AdjFASt", diags);
    auto ss_factor = f.get_double("AdjSSSt", diags);
    auto table =
        read_ed_stations(f, "NTwInpSt", {"HtFract", "TMassDen", "TwFAStif", "TwSSStif"}, diags);
    if (!mass_factor || !fa_factor || !ss_factor || !table) return std::nullopt;
    for (const char* key : {"AdjTwMa", "AdjFASt", "AdjSSSt"})
        if (!(*f.get_double(key, diags) > 0))
            diags.error(diag::Kind::InvalidValue, f.location(key),
                        "an adjustment factor must be > 0");
    for (std::size_t r = 0; r < table->values.size(); ++r) {
        const std::vector<double>& v = table->values[r];
        if (!(v[1] > 0 && v[2] > 0 && v[3] > 0))
            diags.error(diag::Kind::InvalidValue, {file, table->lines[r], 1},
                        "tower mass and stiffness must be > 0");
        Station s;
        s.s = v[0];
        s.mass_per_length = *mass_factor * v[1];
        s.EI_y = *fa_factor * v[2];
        s.EI_x = *ss_factor * v[3];
        beam.stations.push_back(s);
    }
    if (diags.error_count() > errors) return std::nullopt;
    return beam;
}

} // namespace yamsc::beam
