// Beams from ElastoDyn tower and blade files: the files are read by
// formats/elastodyn/beam_file.hpp; here their numbers take the beam's axes.
#include "beam/elastodyn.hpp"

#include "elastodyn/beam_file.hpp"

#include <cmath>

namespace yamsc::beam {

namespace {

std::optional<Beam> read_elastodyn(elastodyn::BeamKind kind,
                                   const std::shared_ptr<const diag::SourceFile>& file,
                                   double length, const std::vector<std::string>& modes,
                                   diag::Diagnostics& diags) {
    const int errors = diags.error_count();
    if (!(length > 0 && std::isfinite(length)))
        diags.error(diag::Kind::InvalidValue, {file, 0, 0},
                    "the length of a beam from an ElastoDyn file must be > 0");
    const auto read = elastodyn::read_beam_file(kind, file, modes, diags);
    if (!read || diags.error_count() > errors) return std::nullopt;
    const bool tower = kind == elastodyn::BeamKind::tower;
    Beam beam;
    beam.length = length;
    beam.integrated_shapes = !tower; // ElastoDyn's tower: SHP at its elements
    for (const elastodyn::ModeShape& m : read->modes)
        beam.modes.push_back({m.name, m.direction, m.coeffs, m.damping_ratio, m.stiffness_tuner});
    const double deg = std::acos(-1.0) / 180;
    // Displacement along x (fore-aft, flap) is resisted by EI_y, along y by EI_x.
    // ElastoDyn turns a blade's principal axes by StrcTwst about -z (TwistedSF: the
    // flap curvature points along (cos, -sin)): our twist is about +z.
    for (const elastodyn::Section& s : read->sections)
        beam.stations.push_back({s.fraction, s.mass_per_length, s.stiffness_y, s.stiffness_x,
                                 tower ? 0.0 : -s.twist_deg * deg});
    return beam;
}

} // namespace

const std::vector<std::string>& elastodyn_tower_modes() {
    return elastodyn::mode_names(elastodyn::BeamKind::tower);
}

const std::vector<std::string>& elastodyn_blade_modes() {
    return elastodyn::mode_names(elastodyn::BeamKind::blade);
}

std::optional<Beam> read_elastodyn_tower(const std::shared_ptr<const diag::SourceFile>& file,
                                         double length, const std::vector<std::string>& modes,
                                         diag::Diagnostics& diags) {
    return read_elastodyn(elastodyn::BeamKind::tower, file, length, modes, diags);
}

std::optional<Beam> read_elastodyn_blade(const std::shared_ptr<const diag::SourceFile>& file,
                                         double length, const std::vector<std::string>& modes,
                                         diag::Diagnostics& diags) {
    return read_elastodyn(elastodyn::BeamKind::blade, file, length, modes, diags);
}

} // namespace yamsc::beam
