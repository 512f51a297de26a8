#pragma once
// An AeroDyn airfoil file as the blade-element code's aero::Airfoil: angles in
// radians, and every unsteady-aerodynamics constant the file leaves out or gives as
// "default" computed from the polar as AeroDyn's AirfoilInfo does
// (CalculateUACoeffs): Cd0 at the least drag within +/-20 deg, alphaUpper and
// alphaLower where the smoothed Cn slope falls below 90 % of its peak, C_nalpha,
// C_lalpha and alpha0 by least squares between them, Cm0 at alpha0, alpha1 and
// alpha2 where the separation function f crosses 0.7, Cn1 and Cn2 the static Cn
// there, the fixed defaults (T_f0 3, T_V0 6, T_p 1.7, T_VL 11, b1 0.14, b2 0.53,
// b5 5, A1 0.3, A2 0.7, A5 1, St_sh 0.19, x_cp_bar 0.2, UACutout 45 deg,
// filtCutOff 0.5, eta_e 1, k and S terms 0). A table of constant coefficients has
// no unsteady constants (AeroDyn turns unsteady aerodynamics off there).
#include "aerodyn/airfoil_file.hpp"
#include "yamsc/aero/airfoil.hpp"
#include "yamsc/aero/rotor_input.hpp"

#include <vector>

namespace yamsc::aerodyn_input {

/// The static separation function of a table, as AirfoilInfo tabulates it beside
/// the polar for the unsteady models: f (0 .. 1) and the normal-force (or, for
/// UA_Mod 4 and 6, lift) coefficient of fully separated and fully attached flow,
/// one value per row of the table.
struct SeparationFunction {
    std::vector<double> f, fully_separated, fully_attached;
};

/// Whether the coefficients of a table do not change with the angle of attack
/// (fewer than three rows, or every row the same), as AirfoilInfo decides it.
bool constant_polar(const aero::PolarTable& table);

/// The unsteady constants of `table` (alpha in rad): the entries given, the others
/// computed. `model` matters as in AeroDyn: UA_Mod 4 and 6 work on Cl, the others
/// on Cn, and those snap alphaLower and alphaUpper to rows of the table.
aero::UnsteadyConstants unsteady_constants(const aero::PolarTable& table,
                                           const aerodyn::UnsteadyEntries& given,
                                           aero::UnsteadyModel model);

/// The separation function of `table` with its constants `k` (which, for the
/// Cn-based models, get alphaLower and alphaUpper snapped to rows of the table).
SeparationFunction separation_function(const aero::PolarTable& table, aero::UnsteadyConstants& k,
                                       aero::UnsteadyModel model);

/// The airfoil of a file: every table, angles in radians, unsteady constants filled.
aero::Airfoil to_airfoil(const aerodyn::AirfoilFile& file, aero::UnsteadyModel model);

} // namespace yamsc::aerodyn_input
