#pragma once
// A straight beam along its body z axis, described by its section properties and
// shape functions, and its Standard Input Data (paper Appendix B and C). Produced
// by the model checker (inline `beam {}` blocks) or by the ElastoDyn readers;
// turned into a sid::Sid by make_sid().
#include "sid/sid.hpp"

#include <string>
#include <vector>

namespace yamsc::beam {

/// Section properties at a station; piecewise linear in between.
struct Station {
    double s = 0;               // fraction of the length from the root, 0..1
    double mass_per_length = 0; // kg/m
    double EI_x = 0;            // bending stiffness about x (resists displacement along y)
    double EI_y = 0;            // bending stiffness about y (resists displacement along x)
    double twist = 0;           // structural twist of the principal axes about z [rad]
};

/// A shape function u(z) = e * sum_p coeffs[p] (z/L)^p, e = x or y of the body.
/// With structural twist the polynomial gives the displacement along the twisted
/// principal axis (its second derivative is the curvature about that axis) and the
/// body-axes shape is integrated from that curvature, as ElastoDyn does for blades.
struct Mode {
    std::string name;
    int direction = 0;          // 0: x, 1: y
    std::vector<double> coeffs; // coefficient of (z/L)^p at index p
    double damping_ratio = 0;   // fraction of critical (not percent)
    double stiffness_tuner = 1; // ElastoDyn's modal stiffness tuner: Ke(j,k) *= sqrt(t_j t_k)
};

struct Beam {
    double length = 0;
    std::vector<Station> stations; // sorted by s, covering 0..1
    std::vector<Mode> modes;       // in SID order
    int integration_stations = 50; // points of the integration grid (also the SID nodes)
    // > 0: ElastoDyn's discretization instead (Grid::elements): this many equal
    // elements, properties at their centres, midpoint sums. The SID then equals
    // ElastoDyn's lumped blade or tower (docs/beam-preprocessing.md).
    int elements = 0;
    // With `elements`: true for ElastoDyn's blades, whose shapes are the running
    // integrals of the (twisted) curvature on the elements (TwistedSF); false for its
    // tower, whose shapes and slopes are the polynomial's own values (SHP). Without
    // `elements` the exact integrals make both the same.
    bool integrated_shapes = true;
};

} // namespace yamsc::beam
