#pragma once
// An airfoil as AeroDyn's AirfoilInfo holds it: polar tables (angle of attack in
// radians, Cl, Cd and optionally Cm), each with the Beddoes-Leishman constants of
// the unsteady-aerodynamics models. Plain data: the file reader
// (formats/aerodyn) fills it, the blade-element code (yamsc/aero/*) reads it.
#include <optional>
#include <string>
#include <vector>

namespace yamsc::aero {

// The unsteady-aerodynamics constants of one table, as in AeroDyn's airfoil file
// (angles in radians here, degrees in the file). A value the file gives as
// "default" is filled by the reader as AirfoilInfo computes it.
struct UnsteadyConstants {
    double alpha0 = 0, alpha1 = 0, alpha2 = 0; // zero lift; f = 0.7 above/below alpha0 [rad]
    double eta_e = 1, C_nalpha = 0, C_lalpha = 0;
    double T_f0 = 3, T_V0 = 6, T_p = 1.7, T_VL = 11;
    double b1 = 0.14, b2 = 0.53, b5 = 5, A1 = 0.3, A2 = 0.7, A5 = 1;
    double S1 = 0, S2 = 0, S3 = 0, S4 = 0;
    double Cn1 = 0, Cn2 = 0, St_sh = 0.19, Cd0 = 0, Cm0 = 0;
    double k0 = 0, k1 = 0, k2 = 0, k3 = 0, k1_hat = 0, x_cp_bar = 0.2;
    double UACutout = 45 * 3.14159265358979323846 / 180; // [rad]
    double filtCutOff = 0.5;                             // reduced frequency [-]
    double alphaUpper = 0, alphaLower = 0;               // fully attached range [rad] (HGM, Oye)
};

// One table of an airfoil file: one Reynolds number and one control setting.
struct PolarTable {
    double reynolds = 0;       // [million]
    double user_prop = 0;      // control setting
    std::vector<double> alpha; // [rad], increasing, -pi .. pi
    std::vector<double> cl, cd;
    std::vector<double> cm;                    // empty when the file has no Cm column
    std::optional<UnsteadyConstants> unsteady; // InclUAdata
};

enum class Interpolation { linear = 1, cubic_spline = 3 };

struct Airfoil {
    std::string name;                                    // the file's name, for messages
    Interpolation interpolation = Interpolation::linear; // InterpOrd
    double non_dimensional_area = 1;                     // NonDimArea
    std::vector<PolarTable> tables;                      // NumTabs (AFTabMod 1 uses the first)
};

} // namespace yamsc::aero
