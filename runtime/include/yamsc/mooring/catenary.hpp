#pragma once
// One quasi-static mooring line: the elastic catenary with seabed contact and
// Coulomb friction on the seabed, without bending stiffness or line dynamics.
// These are the equations MAP++ and FAST's `Catenary` routine solve (Jonkman,
// NREL/TP-500-41958, section 4.1); the conventions are in docs/mooring.md.

namespace yamsc::runtime::mooring {

/// A line's properties, per unit unstretched length where per length.
struct LineProperties {
    double length = 0;           // unstretched length L [m]
    double axial_stiffness = 0;  // EA [N]
    double weight_in_fluid = 0;  // w: weight minus buoyancy per length [N/m], > 0
    double seabed_friction = -1; // CB [-]; negative: no seabed (the line may hang below the anchor)
};

/// The fairlead's position relative to the anchor in the line's vertical plane.
struct Span {
    double horizontal = 0; // x_F >= 0 [m]
    double vertical = 0;   // z_F, the fairlead above the anchor > 0 [m]
};

/// The effective tensions at both ends and how they move with the span.
struct CatenarySolution {
    double fairlead_horizontal = 0; // H_F [N]
    double fairlead_vertical = 0;   // V_F [N], the line pulls the fairlead down by it
    double anchor_horizontal = 0;   // H_A [N]
    double anchor_vertical = 0;     // V_A [N]
    double length_on_seabed = 0;    // L_B [m], unstretched
    // d(H_F, V_F)/d(x_F, z_F), row-major 2 x 2: the line's stiffness in its plane.
    double stiffness[4] = {0, 0, 0, 0};
    int iterations = 0;
};

/// Solves the line for (H_F, V_F). `guess`, when positive, starts Newton's
/// iteration there (the last solution of the same line); otherwise the start
/// is Peyrot and Goulois's, as FAST's. Throws std::runtime_error when the line
/// has no solution (longer than the "L" shape along the seabed and up to the
/// fairlead, a non-positive property, or no convergence).
CatenarySolution solve_catenary(const LineProperties& line, const Span& span,
                                const CatenarySolution* guess = nullptr);

/// The span x_F, z_F that tensions (H_F, V_F) hold the line in, and its
/// derivatives d(x_F, z_F)/d(H_F, V_F) (row-major 2 x 2): the equations the
/// solver inverts, for tests and for the line's profile.
Span catenary_span(const LineProperties& line, double horizontal, double vertical,
                   double* derivatives = nullptr);

} // namespace yamsc::runtime::mooring
