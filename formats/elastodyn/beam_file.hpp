#pragma once
// OpenFAST ElastoDyn tower ("TWR") and blade ("BLD") input files. Both have the same
// skeleton (polynomial mode shapes with damping and stiffness tuners, three adjustment
// factors, a table of distributed properties per span fraction), read by one reader;
// the keys of each are listed once in beam_file.cpp. What the numbers mean for a beam
// (its axes, the sign of the twist) is the beam stage's (compiler/beam/elastodyn.hpp).
// Bad input gives located diagnostics and nullopt.
#include "diag/diagnostics.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::elastodyn {

enum class BeamKind { tower, blade };

/// One mode: u(z) = sum_p coeffs[p] (z/L)^p, p = 0..6 (0 and 1 are 0: a clamped root),
/// scaled to 1 at the tip.
struct ModeShape {
    std::string name;           // fa1, fa2, ss1, ss2; flap1, flap2, edge1
    int direction = 0;          // 0: along x (fore-aft, flap), 1: along y (side-side, edge)
    std::vector<double> coeffs; // coefficient of (z/L)^p at index p
    double damping_ratio = 0;   // fraction of critical (the file gives percent)
    double stiffness_tuner = 1; // FAStTunr, SSStTunr, FlStTunr; 1 for the edge mode
};

/// One row of the distributed properties, the file's adjustment factors applied.
struct Section {
    double fraction = 0;        // HtFract, BlFract: 0 at the root .. 1 at the tip
    double mass_per_length = 0; // TMassDen * AdjTwMa, BMassDen * AdjBlMs [kg/m]
    double stiffness_x = 0; // against displacement along x: TwFAStif * AdjFASt, FlpStff * AdjFlSt
    double stiffness_y = 0; // along y: TwSSStif * AdjSSSt, EdgStff * AdjEdSt [N m^2]
    double twist_deg = 0;   // StrcTwst of blades, 0 for towers [deg]
};

struct BeamFile {
    std::vector<Section> sections; // by rising fraction, from 0 to 1
    std::vector<ModeShape> modes;  // as requested, in that order
};

/// The names of the modes a file of `kind` describes: fa1, fa2, ss1, ss2 or flap1, flap2, edge1.
const std::vector<std::string>& mode_names(BeamKind kind);

/// The sections of `file` and its `modes` (names of mode_names(kind), in the order wanted).
std::optional<BeamFile> read_beam_file(BeamKind kind,
                                       const std::shared_ptr<const diag::SourceFile>& file,
                                       const std::vector<std::string>& modes,
                                       diag::Diagnostics& diags);

} // namespace yamsc::elastodyn
