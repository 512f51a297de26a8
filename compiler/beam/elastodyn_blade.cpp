// The ElastoDyn blade file (OpenFAST ElastoDyn "BLD" input): distributed properties
// per span fraction, structural twist, and polynomial flap / edge mode shapes.
#include "beam/elastodyn.hpp"
#include "beam/elastodyn_beam.hpp"

#include <cmath>

namespace yamsc::beam {

const std::vector<std::string>& elastodyn_blade_modes() {
    static const std::vector<std::string> names{"flap1", "flap2", "edge1"};
    return names;
}

std::optional<Beam> read_elastodyn_blade(const std::shared_ptr<const diag::SourceFile>& file,
                                         double length, const std::vector<std::string>& modes,
                                         diag::Diagnostics& diags) {
    const ElastoDynFile f(file);
    const int errors = diags.error_count();
    Beam beam;
    beam.length = length;
    check_ed_length(f, length, diags);
    // Flap bends about the principal axis of FlpStff (displacement along x at zero
    // twist), edge about that of EdgStff (along y). The edge mode has no tuner.
    const std::vector<EdModeKeys> known{{"flap1", "BldFl1Sh", "BldFlDmp(1)", "FlStTunr(1)", 0},
                                        {"flap2", "BldFl2Sh", "BldFlDmp(2)", "FlStTunr(2)", 0},
                                        {"edge1", "BldEdgSh", "BldEdDmp(1)", "", 1}};
    read_ed_modes(f, modes, known, beam, diags);
    auto mass_factor = f.get_double("AdjBlMs", diags);
    auto flap_factor = f.get_double("AdjFlSt", diags);
    auto edge_factor = f.get_double("AdjEdSt", diags);
    // PitchAxis (aerodynamic centre location) is read for the table's shape, not used.
    auto table = read_ed_stations(
        f, "NBlInpSt", {"BlFract", "PitchAxis", "StrcTwst", "BMassDen", "FlpStff", "EdgStff"},
        diags);
    if (!mass_factor || !flap_factor || !edge_factor || !table) return std::nullopt;
    for (const char* key : {"AdjBlMs", "AdjFlSt", "AdjEdSt"})
        if (!(*f.get_double(key, diags) > 0))
            diags.error(diag::Kind::InvalidValue, f.location(key),
                        "an adjustment factor must be > 0");
    const double deg = std::acos(-1.0) / 180;
    for (std::size_t r = 0; r < table->values.size(); ++r) {
        const std::vector<double>& v = table->values[r];
        if (!(v[3] > 0 && v[4] > 0 && v[5] > 0))
            diags.error(diag::Kind::InvalidValue, {file, table->lines[r], 1},
                        "blade mass and stiffness must be > 0");
        Station s;
        s.s = v[0];
        // ElastoDyn turns the principal axes by StrcTwst about -z (TwistedSF: the flap
        // curvature points along (cos, -sin)): our twist is about +z.
        s.twist = -v[2] * deg;
        s.mass_per_length = *mass_factor * v[3];
        s.EI_y = *flap_factor * v[4];
        s.EI_x = *edge_factor * v[5];
        beam.stations.push_back(s);
    }
    if (diags.error_count() > errors) return std::nullopt;
    return beam;
}

} // namespace yamsc::beam
