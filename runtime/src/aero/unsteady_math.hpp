#pragma once
// Helpers shared by the unsteady-airfoil models: angles and blending as NWTC_Num's
// MPi2Pi, AddOrSub2Pi and BlendCosine, UA's input fix and steady blending.
#include "yamsc/aero/unsteady_airfoil.hpp"

#include <cmath>

namespace yamsc::aero::unsteady_detail {

constexpr double pi = 3.14159265358979323846;

// To [-pi, pi).
inline double wrap_pi(double a) {
    if (a >= -pi && a < pi) return a;
    a = std::fmod(a + pi, 2 * pi);
    if (a < 0) a += 2 * pi;
    return a - pi;
}

// a shifted by whole turns to lie within pi of reference.
inline double near(double reference, double a) {
    while (a - reference > pi) a -= 2 * pi;
    while (a - reference < -pi) a += 2 * pi;
    return a;
}

// 0 at or below lower, 1 at or above upper, a cosine in between.
inline double blend_cosine(double x, double lower, double upper) {
    if (x >= upper) return 1;
    if (x <= lower || lower >= upper) return 0;
    return 0.5 * (1 - std::cos((x - lower) / (upper - lower) * pi));
}

constexpr double u_min = 0.01; // UA_u_min [m/s]

// alpha wrapped, U kept from zero (UA_fixInputs).
inline UnsteadyInput fixed(const UnsteadyInput& in) {
    UnsteadyInput u = in;
    u.alpha = wrap_pi(u.alpha);
    if (std::abs(u.U) < u_min) {
        u.U = std::copysign(u_min, u.U);
        u.v_ac_n = std::sin(u.alpha) * u.U;
        u.v_ac_c = std::cos(u.alpha) * u.U;
    }
    return u;
}

// Weight of the unsteady model against the steady polar: 0 from UACutout on and at zero
// speed, a cosine over the 5 deg below UACutout and the 1 m/s above zero.
inline double unsteady_weight(const UnsteadyAirfoil& af, const UnsteadyInput& u) {
    const double w1 =
        1 - blend_cosine(std::abs(u.alpha), af.cutout_blend(), af.constants().UACutout);
    return w1 * blend_cosine(std::abs(u.U), u_min, 1.0);
}

// Outputs blended toward the steady polar by that weight (UA_BlendSteady).
inline void blend_steady(const UnsteadyAirfoil& af, const UnsteadyInput& u, UnsteadyOutput& y) {
    const UnsteadyConstants& k = af.constants();
    y.weight = unsteady_weight(af, u);
    if (y.weight >= 1) return;
    const auto p = af.at(u.alpha);
    const double ca = std::cos(u.alpha), sa = std::sin(u.alpha);
    const double cn = p.cl * ca + (p.cd - k.Cd0) * sa, cc = p.cl * sa - (p.cd - k.Cd0) * ca;
    const double w = y.weight;
    y.cn = y.cn * w + (1 - w) * cn;
    y.cc = y.cc * w + (1 - w) * cc;
    y.cm = y.cm * w + (1 - w) * p.cm;
    y.cl = y.cl * w + (1 - w) * p.cl;
    y.cd = y.cd * w + (1 - w) * p.cd;
}

} // namespace yamsc::aero::unsteady_detail
