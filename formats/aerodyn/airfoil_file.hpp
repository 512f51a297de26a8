#pragma once
// An AeroDyn airfoil file (AirfoilInfo v1.01): InterpOrd, NonDimArea, the shape
// (NumCoords, often in a file included with '@'), NumTabs tables, each with Re,
// UserProp, InclUAdata and its unsteady-aerodynamics entries, and NumAlf rows whose
// columns the AeroDyn primary file chooses (InCol_Alfa, InCol_Cl, ...). Read in
// order as AirfoilInfo's ReadAFfile does: an unsteady entry left out or given as
// "default" stays unset here (the conversion computes it as AirfoilInfo does).
// Values as in the file: degrees. Bad input: located errors and nullopt.
#include "aerodyn/lines.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace yamsc::aerodyn {

/// Which column of a table row holds what (1-based; 0: no such column), from the
/// AeroDyn primary file.
struct AirfoilColumns {
    int alpha = 1, cl = 2, cd = 3, cm = 4, cpmin = 0;
};

/// The unsteady-aerodynamics entries of a table, as written (angles in degrees);
/// nullopt: left out or "default".
struct UnsteadyEntries {
    std::optional<double> alpha0, alpha1, alpha2, alphaUpper, alphaLower;
    std::optional<double> eta_e, C_nalpha, C_lalpha;
    std::optional<double> T_f0, T_V0, T_p, T_VL, b1, b2, b5, A1, A2, A5;
    std::optional<double> S1, S2, S3, S4, Cn1, Cn2, St_sh, Cd0, Cm0;
    std::optional<double> k0, k1, k2, k3, k1_hat, x_cp_bar;
    std::optional<double> UACutout, UACutout_delta, filtCutOff;
};

struct AirfoilTable {
    double reynolds = 0;       // Re [million]
    double user_prop = 0;      // UserProp (Ctrl in older files)
    bool has_unsteady = false; // InclUAdata
    UnsteadyEntries unsteady;
    std::vector<double> alpha; // [deg], strictly rising
    std::vector<double> cl, cd;
    std::vector<double> cm, cpmin; // empty without their column
    diag::Location at;             // its NumAlf
};

struct AirfoilFile {
    std::shared_ptr<const diag::SourceFile> file;
    std::optional<int> interp_order;               // InterpOrd: 1 or 3; nullopt: "default" (1)
    std::optional<double> relative_thickness;      // RelThickness, when given
    double non_dimensional_area = 1;               // NonDimArea
    std::vector<std::pair<double, double>> coords; // NumCoords rows (x/c, y/c)
    std::vector<AirfoilTable> tables;              // NumTabs
};

/// Reads an airfoil file; '@' lines read the files they name through `includes`
/// (paths relative to the including file). Errors: missing or bad entries, counts
/// out of range, rows too short or not numbers, fewer rows than announced, alpha
/// not rising, a constant table whose ends differ. Warnings: a table not from -180
/// to 180 deg with equal ends; InterpOrd 3 (interpolated linearly); Re <= 0.
std::optional<AirfoilFile> read_airfoil_file(const std::shared_ptr<const diag::SourceFile>& file,
                                             const AirfoilColumns& columns,
                                             diag::Diagnostics& diags,
                                             const IncludeReader& includes = includes_from_disk());

} // namespace yamsc::aerodyn
