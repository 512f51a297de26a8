#pragma once
// Steady blade-element momentum theory of one blade element, as AeroDyn v15
// (OpenFAST v4/v5, BEM_Mod 1 "legacy") solves it: Ning's single residual in the
// inflow angle phi, bracketed in AeroDyn's three regions and solved with Brent's
// method (it cannot fail to converge; without a root, phi is the wake-free
// angle and the inductions are zero), Prandtl's tip and hub losses, Buhl's
// high-induction correction, the propeller-brake region, the optional drag
// terms, and the Pitt/Peters skewed-wake redistribution of the axial induction.
// The element frame is AeroDyn's "without sweep, pitch and twist" frame: x along
// the (coned) rotor axis downwind, y opposite to the blade's motion (from the
// leading to the trailing edge), z along the blade.
#include "yamsc/aero/airfoil.hpp"
#include "yamsc/aero/polar.hpp"
#include "yamsc/aero/rotor_input.hpp"

namespace yamsc::aero {

// The switches of the solve, taken once from RotorInput.
struct BemOptions {
    bool tip_loss = true, hub_loss = true, tangential_induction = true;
    bool axial_drag = false, tangential_drag = false;
    double tolerance = 5e-10; // IndToler; AeroDyn's double-precision default
    int max_iterations = 100;
    // Brent stops when the inflow angle's bracket is below this [rad]: AeroDyn's
    // 1e-6 (sub_brent) leaves the loads rough at 1e-6 of their size, which a
    // Newton method or a difference quotient sees; trim and lin ask for less.
    double angle_tolerance = 1e-6;
    bool skew_redistribution = true;                           // Skew_Mod 1 with SkewRedistr_Mod 1
    double skew_factor = 15.0 * 3.14159265358979323846 / 32.0; // SkewRedistrFactor
    bool use_pitching_moment = true;                           // UseBlCm
};
BemOptions bem_options(const RotorInput& input);

struct ElementInput {
    double vx = 0, vy = 0; // relative inflow, axial (downwind) and tangential [m/s]
    double r = 0;          // distance from the rotor axis (solidity) [m]
    // Distances along the blade from the apex (AeroDyn's zLocal, zHub, zTip) for
    // Prandtl's losses [m].
    double z = 0, z_hub = 0, z_tip = 0;
    int blades = 3;
    double theta = 0; // twist + pitch [rad]
    double chord = 0; // [m]
    const Airfoil* airfoil = nullptr;
    // The airfoil's first table with its segment index (BemRotor sets it), or
    // null: the table is searched (the same coefficients).
    const IndexedPolar* polar = nullptr;
    // Skewed wake: chi0 the angle between the rotor axis and the disk-averaged
    // relative wind, psi the blade's azimuth from the skew plane (AeroDyn's psi_s),
    // tip_ratio r / R_tip [rad, rad, -].
    double chi0 = 0, psi = 0, tip_ratio = 0;
    // Blend of the inductions at low tip-speed ratio (AeroDyn's BEM_weight:
    // 1 above TSR 2, 0 below TSR 1); see induction_weight().
    double weight = 1;
    // AeroDyn's constraint state: the previous phi orders the search regions and,
    // when it was a valid root, is tried first.
    double phi_guess = 0;
    bool guess_valid = false;
};

struct ElementSolution {
    double phi = 0;   // inflow angle after the skew correction [rad]
    double alpha = 0; // phi - theta [rad], not wrapped
    double a = 0, ap = 0, F = 1;
    double cl = 0, cd = 0, cm = 0;
    double cx = 0, cy = 0; // normal and tangential force coefficients (with drag)
    double vrel = 0;       // [m/s]
    double fx = 0, fy = 0; // force per length along x and along the motion (BkNjFx, BkNjFy) [N/m]
    double mz = 0;         // pitching moment per length about z [N m/m]
    double phi_bem = 0;    // root of the residual, before the corrections (the state)
    // The inductions at phi_bem before the skew and low-TSR corrections (limited
    // to [-1, 1.5] and [-1, 1]; 0 without a root): DBEMT's quasi-steady input.
    double a_bem = 0, ap_bem = 0;
    bool valid = false; // a BEM root was found (else the wake-free phi)
};

// The element's steady coefficients at alpha: its polar's.
inline Coefficients coefficients(const ElementInput& in, double alpha) {
    return in.polar ? in.polar->at(alpha) : lookup(*in.airfoil, alpha);
}

// The residual of Ning's equation at phi and the inductions it implies (before
// the limits and corrections); exposed for tests.
struct Residual {
    double f = 0, a = 0, ap = 0, k = 0, kp = 0, F = 1;
    bool valid = true; // k in the range of the region (AeroDyn's IsValidSolution)
};
Residual bem_residual(const ElementInput& in, const BemOptions& opt, double phi);

// What every residual of one element shares (its loss constants, solidity,
// Vy/Vx), computed once per solve with the operations bem_residual would repeat.
struct ElementTerms {
    ElementTerms(const ElementInput& in, const BemOptions& opt);
    const ElementInput& in;
    const BemOptions& opt;
    double c_tip, c_hub; // Prandtl's loss constants, tip and hub
    bool fixed;          // AeroDyn's FixedInductions: a = 1, a' = 0
    bool no_inflow;      // Vx or Vy below 1 mm/s
    double sigma;        // B c / (2 pi r)
    double lambda;       // Vy / Vx
};
Residual bem_residual(const ElementTerms& element, double phi);

// Solves the element: the residual's root, the inductions, the coefficients and
// the loads per length for air density rho. Allocates nothing.
ElementSolution solve_element(const ElementInput& in, const BemOptions& opt, double rho);
// solve_element in two parts. solve_inductions: the root and the inductions at
// it (phi_bem, valid, F, a_bem, ap_bem), all DBEMT needs of the steady solve;
// finish_element: the skew correction, the low-TSR blend, the inflow angle,
// coefficients and loads (what DBEMT's filtered inductions replace).
ElementSolution solve_inductions(const ElementInput& in, const BemOptions& opt);

// What one element's last solves leave for the next one's warm bracket: the
// signs of the residual at the momentum region's ends, from the last search
// that evaluated them and found its root inside that region by Brent, and the
// residual's slope near the last root (the step to the next root is guessed
// from it).
struct BracketMemory {
    bool ends_known = false;
    bool near_end_nonnegative = false; // f at the region's end near phi = 0 is >= 0
    double slope = 0;                  // df/dphi by the last root's final bracket
};
// solve_inductions with a warm bracket (docs/aerodynamics.md): after AeroDyn's
// test of the previous root, the root is first bracketed between it and one
// point on the side AeroDyn's search would narrow to, the memory's end signs
// standing in for the region's ends; Brent then solves in that bracket. When it
// holds no sign change or its root is not valid, AeroDyn's full search runs and
// refreshes the memory. The root agrees with the full search's to Brent's
// tolerances (opt.tolerance, opt.angle_tolerance), not bit for bit.
ElementSolution solve_inductions(const ElementInput& in, const BemOptions& opt,
                                 BracketMemory& memory);
void finish_element(const ElementInput& in, const BemOptions& opt, double rho, ElementSolution& s);

// The element at given inductions a, a' (after every correction): its inflow
// angle, coefficients and loads per length, written into s (s's BEM root and
// F are left as they are). solve_element ends with it; a frozen wake calls it
// with the operating point's inductions.
void element_loads(const ElementInput& in, const BemOptions& opt, double rho, double a, double ap,
                   ElementSolution& s);

// The element's coefficients c (the polar's, or unsteady ones) at its phi and vrel:
// cl, cd, cm (0 without UseBlCm), cx, cy and the loads per length for density rho.
void set_coefficients(ElementSolution& s, const Coefficients& c, double chord, double rho,
                      const BemOptions& opt);

// Prandtl's loss factor of AeroDyn (BEM_Mod 1): tip and hub constants
// B (z_tip - z) / (2 z) and B (z - z_hub) / (2 z_hub) over |sin phi|.
double prandtl_loss(const ElementInput& in, const BemOptions& opt, double phi);

// Axial induction from k = sigma' Cx / (4 F sin^2 phi) in the momentum region:
// k / (1 + k) up to a = 0.4, Buhl's empirical curve above.
double axial_induction_momentum(double k, double F);

// AeroDyn's blend of the inductions at low tip-speed ratio.
double induction_weight(double tsr);

} // namespace yamsc::aero
