#pragma once
// An AeroDyn blade file ("AERODYN v15.00.* BLADE DEFINITION INPUT FILE"): NumBlNds
// and a table whose columns are found by name in its header, as AeroDyn's
// ReadBladeInputs does (BlSpn, BlCrvAC, BlSwpAC, BlTwist, BlChord and BlAFID
// required; BlCrvAng and the buoyancy and marine columns optional, 0 when absent).
// Values as in the file: degrees, metres. Bad input: located errors and nullopt.
#include "diag/diagnostics.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace yamsc::aerodyn {

struct BladeNodeRow {
    double span = 0;        // BlSpn [m]
    double curve_ac = 0;    // BlCrvAC [m]
    double sweep_ac = 0;    // BlSwpAC [m]
    double curve_angle = 0; // BlCrvAng [deg]
    double twist = 0;       // BlTwist [deg]
    double chord = 0;       // BlChord [m]
    int airfoil_id = 1;     // BlAFID, 1-based
    // Optional columns of newer files: thickness, buoyancy and marine (MHK) coefficients.
    double t_c = 0, cb = 0, cen_bn = 0, cen_bt = 0, cpn = 0, cpt = 0, can = 0, cat = 0, cam = 0;
    diag::Location at;            // the row
    diag::Location airfoil_id_at; // its BlAFID
};

struct BladeFile {
    std::shared_ptr<const diag::SourceFile> file;
    std::vector<BladeNodeRow> nodes; // NumBlNds rows, by rising BlSpn from 0
    bool has_curve_angle = false;    // the BlCrvAng column is present
};

/// Reads an AeroDyn blade file. Errors: a missing or bad entry or column, a row too
/// short or not numbers, fewer rows than NumBlNds, BlSpn not starting at 0 or not
/// rising, BlChord <= 0, BlAFID not a positive integer. Warnings: buoyancy and
/// marine columns that are not zero (not converted).
std::optional<BladeFile> read_blade_file(const std::shared_ptr<const diag::SourceFile>& file,
                                         diag::Diagnostics& diags);

} // namespace yamsc::aerodyn
