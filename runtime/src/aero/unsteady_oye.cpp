// UA_Mod 6: Oye's dynamic stall, a first-order lag of the separation point x4 toward
// the steady separation function at the 3/4-chord angle of attack (UnsteadyAero's
// UA_CalcContStateDeriv, UA_CalcOutput and its RK4/AB4/ABM4 integrators).
#include "unsteady_math.hpp"
#include "yamsc/aero/unsteady_airfoil.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::aero {

using unsteady_detail::blend_steady;
using unsteady_detail::fixed;
using unsteady_detail::near;
using unsteady_detail::u_min;
using unsteady_detail::unsteady_weight;

namespace {

// Tu = c / (2 U), kept within [0.001, 50] s (Get_Tu).
double time_unit(double U, double chord) {
    return std::clamp(chord / (2 * std::max(U, u_min)), 0.001, 50.0);
}

double alpha_34(const UnsteadySettings& s, double chord, const UnsteadyInput& u) {
    return std::atan2(u.v_ac_n + u.omega * s.d_34_to_ac * chord, u.v_ac_c);
}

// Inputs at t + theta dt, linear between t and t + dt (the angle along the short way).
UnsteadyInput between(const UnsteadyInput& a, const UnsteadyInput& b, double theta) {
    UnsteadyInput u;
    u.U = a.U + theta * (b.U - a.U);
    u.alpha = a.alpha + theta * (near(a.alpha, b.alpha) - a.alpha);
    u.omega = a.omega + theta * (b.omega - a.omega);
    u.v_ac_n = a.v_ac_n + theta * (b.v_ac_n - a.v_ac_n);
    u.v_ac_c = a.v_ac_c + theta * (b.v_ac_c - a.v_ac_c);
    return u;
}

void require_model(const UnsteadySettings& s) {
    if (s.model != UnsteadyModel::oye)
        throw std::invalid_argument("unsteady aerodynamics: these states are UA_Mod 6's");
}

double rk4(const UnsteadyAirfoil& af, const UnsteadySettings& s, double c, double dt,
           const UnsteadyInput& u0, const UnsteadyInput& u1, double x) {
    const UnsteadyInput um = between(u0, u1, 0.5);
    const double k1 = dt * oye_derivative(af, s, c, u0, x);
    const double k2 = dt * oye_derivative(af, s, c, um, x + 0.5 * k1);
    const double k3 = dt * oye_derivative(af, s, c, um, x + 0.5 * k2);
    const double k4 = dt * oye_derivative(af, s, c, u1, x + k3);
    return x + (k1 + 2 * k2 + 2 * k3 + k4) / 6;
}

// Adams-Bashforth 4 with RK4 for the steps n <= 2 (UA_AB4): the history holds zeros
// until filled, as OpenFAST's does.
double ab4(const UnsteadyAirfoil& af, const UnsteadySettings& s, double c, double dt,
           const UnsteadyInput& u0, const UnsteadyInput& u1, OyeState& x) {
    if (x.n_last < x.n) {
        x.xdot[3] = x.xdot[2];
        x.xdot[2] = x.xdot[1];
        x.xdot[1] = x.xdot[0];
        x.n_last = x.n;
    }
    x.xdot[0] = oye_derivative(af, s, c, u0, x.x4);
    if (x.n <= 2) return rk4(af, s, c, dt, u0, u1, x.x4);
    return x.x4 + dt / 24 * (55 * x.xdot[0] - 59 * x.xdot[1] + 37 * x.xdot[2] - 9 * x.xdot[3]);
}

} // namespace

double oye_steady_x4(const UnsteadyAirfoil& af, const UnsteadySettings& s, double chord,
                     const UnsteadyInput& in) {
    return af.at(alpha_34(s, chord, fixed(in))).f_st;
}

double oye_derivative(const UnsteadyAirfoil& af, const UnsteadySettings& s, double chord,
                      const UnsteadyInput& in, double x4) {
    const UnsteadyInput u = fixed(in);
    const double T_f = af.constants().T_f0 * time_unit(u.U, chord);
    return (af.at(alpha_34(s, chord, u)).f_st - std::clamp(x4, 0.0, 1.0)) / T_f;
}

UnsteadyOutput evaluate(const UnsteadyAirfoil& af, const UnsteadySettings& s, double chord,
                        const UnsteadyInput& in, const OyeState& state) {
    require_model(s);
    const UnsteadyInput u = fixed(in);
    const UnsteadyConstants& k = af.constants();
    UnsteadyOutput y;
    y.k = std::abs(u.omega * chord / (2 * u.U));
    y.Tu = time_unit(u.U, chord);
    y.alpha_34 = alpha_34(s, chord, u);
    y.alpha_E = y.alpha_34;
    const auto p = af.at(y.alpha_E);
    y.x4 = std::clamp(state.first_pass ? p.f_st : state.x4, 0.0, 1.0);
    y.fs_aE = p.f_st;
    y.cl_fs = p.cl_fs;
    y.cl_fa = (near(k.alpha0, y.alpha_E) - k.alpha0) * k.C_lalpha;
    y.cl = y.x4 * y.cl_fa + (1 - y.x4) * y.cl_fs;
    y.cd = p.cd;
    y.cm = p.cm;
    const double ca = std::cos(u.alpha), sa = std::sin(u.alpha);
    y.cn = y.cl * ca + y.cd * sa;
    y.cc = y.cl * sa - y.cd * ca;
    blend_steady(af, u, y);
    return y;
}

void step(const UnsteadyAirfoil& af, const UnsteadySettings& s, double chord, double dt,
          const UnsteadyInput& u_t, const UnsteadyInput& u_next, OyeState& x) {
    require_model(s);
    if (x.first_pass) x.x4 = oye_steady_x4(af, s, chord, u_t);
    switch (s.integrator) {
    case UnsteadyIntegrator::rk4:
        x.x4 = rk4(af, s, chord, dt, u_t, u_next, x.x4);
        break;
    case UnsteadyIntegrator::ab4:
        x.x4 = ab4(af, s, chord, dt, u_t, u_next, x);
        break;
    case UnsteadyIntegrator::abm4: {
        const double x_in = x.x4;
        x.x4 = ab4(af, s, chord, dt, u_t, u_next, x);
        if (x.n > 2) {
            const double pred = oye_derivative(af, s, chord, u_next, x.x4);
            x.x4 = x_in + dt / 24 * (9 * pred + 19 * x.xdot[0] - 5 * x.xdot[1] + x.xdot[2]);
        }
        break;
    }
    }
    x.x4 = std::clamp(x.x4, 0.0, 1.0);
    // Toward the steady state where the outputs are blended toward the steady polar
    // (UA_BlendSteadyStates).
    const double w = unsteady_weight(af, fixed(u_t));
    if (w < 1) x.x4 = w * x.x4 + (1 - w) * oye_steady_x4(af, s, chord, u_t);
    x.first_pass = false;
    ++x.n;
}

} // namespace yamsc::aero
