#pragma once
// Steady coefficients of an airfoil at an angle of attack, as AeroDyn's
// AFI_ComputeAirfoilCoefs gives them for AFTabMod 1 (the first table).
#include "yamsc/aero/airfoil.hpp"

namespace yamsc::aero {

struct Coefficients {
    double cl = 0, cd = 0, cm = 0;
};

// alpha in rad, any value: wrapped to [-pi, pi) first. Linear interpolation
// (InterpOrd 1); a table of one row is constant.
Coefficients lookup(const PolarTable& table, double alpha);
inline Coefficients lookup(const Airfoil& airfoil, double alpha) {
    return lookup(airfoil.tables.front(), alpha);
}

} // namespace yamsc::aero
