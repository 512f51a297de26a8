#pragma once
// Unsteady airfoil aerodynamics (dynamic stall) of one blade element, as AeroDyn's
// UnsteadyAero module computes it for AFTabMod 1 (the airfoil's first table):
//  - UA_Mod 3, Beddoes-Leishman after Minnema/Pierce: discrete states, updated once per
//    time step of size dt (UA_UpdateDiscOtherState); step() gives the outputs at t from
//    the states of t - dt and the inputs at t, then stores the states of t.
//  - UA_Mod 6, Oye: one continuous state (the separation point x4), its derivative,
//    the outputs, and step() with UnsteadyAero's integrators (RK4, AB4, ABM4; AeroDyn
//    and its driver use ABM4, started with RK4 for the first steps).
// Per-airfoil data (polar columns, the separation function of Oye's model) is computed
// once by UnsteadyAirfoil; a step allocates nothing.
#include "yamsc/aero/airfoil.hpp"
#include "yamsc/aero/polar.hpp"
#include "yamsc/aero/rotor_input.hpp"

#include <vector>

namespace yamsc::aero {

enum class UnsteadyIntegrator { rk4 = 1, ab4 = 2, abm4 = 3 }; // UA's IntegrationMethod

// UnsteadyModel (UA_Mod, rotor_input.hpp): minnema_pierce and oye are modelled here.
struct UnsteadySettings {
    UnsteadyModel model = UnsteadyModel::minnema_pierce;
    bool f_lookup = true;        // FLookup (UA_Mod 3)
    double speed_of_sound = 335; // SpdSound [m/s] (Mach number)
    double d_34_to_ac = 0.5;     // 3/4 chord to aerodynamic centre [chord]
    UnsteadyIntegrator integrator = UnsteadyIntegrator::abm4; // UA_Mod 6
};

// The settings an AeroDyn primary file gives (UA_Mod, FLookup, SpdSound).
inline UnsteadySettings unsteady_settings(const RotorInput& rotor) {
    UnsteadySettings s;
    s.model = rotor.unsteady;
    s.f_lookup = rotor.f_lookup;
    s.speed_of_sound = rotor.speed_of_sound;
    return s;
}

// UA's inputs of one element at one time (UA_InputType): AeroDyn's BEM gives alpha,
// U = |relative velocity| and v_ac = U (sin alpha, cos alpha); the pitch rate omega is
// the element's rotation rate about the span axis. Angles in rad.
struct UnsteadyInput {
    double U = 0;      // relative speed [m/s]
    double alpha = 0;  // angle of attack at the aerodynamic centre [rad]
    double omega = 0;  // pitch rate [rad/s], positive nose up
    double v_ac_n = 0; // relative velocity at the aerodynamic centre, normal to the chord [m/s]
    double v_ac_c = 0; // ... along the chord, toward the trailing edge [m/s]
};

// One airfoil prepared for the unsteady models (its first table, AFTabMod 1).
class UnsteadyAirfoil {
public:
    explicit UnsteadyAirfoil(const Airfoil& airfoil);

    // Whether UA can run on this airfoil (UA_TurnOff_param): the table carries UA
    // constants, its coefficients vary, and C_nalpha (UA_Mod 3) or C_lalpha and the
    // separation function (UA_Mod 6) are not zero. AeroDyn computes such elements
    // with the steady polar.
    bool supports(UnsteadyModel model) const;

    struct Point {
        double cl = 0, cd = 0, cm = 0;
        double f_st = 0;  // separation function on Cl (AirfoilInfo, UA_Mod 4-6)
        double cl_fs = 0; // fully separated Cl
    };
    Point at(double alpha) const; // linear in alpha (InterpOrd 1), alpha wrapped to [-pi, pi)
    const UnsteadyConstants& constants() const { return k_; }
    bool has_cm() const { return has_cm_; }
    double cutout_blend() const { return cutout_blend_; } // UACutout - UACutout_delta [rad]

private:
    std::vector<double> alpha_, cl_, cd_, cm_, f_st_, cl_fs_;
    SegmentIndex index_;
    UnsteadyConstants k_;
    bool has_cm_ = false, has_unsteady_ = false, constant_ = false;
    double cutout_blend_ = 0;
};

// Outputs of one element (UA_OutputType) and the internal quantities of the driver's
// output file, to compare and debug.
struct UnsteadyOutput {
    double cl = 0, cd = 0, cm = 0, cn = 0, cc = 0;
    double weight = 1; // 1 = unsteady, 0 = steady (UACutout / low speed blending)
    double k = 0;      // reduced frequency |omega c / (2 U)|
    // UA_Mod 3
    double alpha_filt = 0, alpha_e = 0, alpha_f = 0, X1 = 0, X2 = 0;
    double cn_aq_circ = 0, cn_aq_nc = 0, cn_pot = 0, Dp = 0, cn_prime = 0;
    double fprime = 0, Df = 0, fprimeprime = 0, cn_v = 0, C_V = 0, tau_V = 0;
    double T_f = 0, T_V = 0, cm_v = 0, alpha_prime_f = 0, Dalphaf = 0;
    // UA_Mod 6
    double alpha_34 = 0, alpha_E = 0, Tu = 0, x4 = 0, fs_aE = 0, cl_fs = 0, cl_fa = 0;
};

// UA_Mod 3 state of one element: the discrete states of the previous step (xd%*_minus1)
// and the other states (sigma1, sigma3, FirstPass). Zero-initialized as UA_ReInit does.
struct MinnemaPierceState {
    bool first_pass = true;
    double alpha_filt = 0, q = 0, q_f = 0, Kq_f = 0, Kalpha_f = 0;
    double X1 = 0, X2 = 0, Kprime_alpha = 0, Kprime_q = 0, K3prime_q = 0, Kprimeprime_q = 0;
    double Dp = 0, cn_pot = 0, cn_prime = 0, fprime = 0, fprimeprime = 0, Df = 0;
    double fprime_c = 0, Df_c = 0, alpha_f = 0, Dalphaf = 0;
    double tau_V = 0, cn_v = 0, C_V = 0;
    double sigma1 = 1, sigma3 = 1;
};

// Outputs at t from the state of t - dt and the inputs at t (UA_CalcOutput), then the
// state of t (UA_UpdateStates with the same inputs). On the first call the outputs are
// the steady polar at alpha (FirstPass). chord [m], dt [s].
UnsteadyOutput step(const UnsteadyAirfoil& airfoil, const UnsteadySettings& settings, double chord,
                    double dt, const UnsteadyInput& u, MinnemaPierceState& state);
// The outputs alone, the state unchanged.
UnsteadyOutput evaluate(const UnsteadyAirfoil& airfoil, const UnsteadySettings& settings,
                        double chord, double dt, const UnsteadyInput& u,
                        const MinnemaPierceState& state);

// Everything UnsteadyAero's ComputeKelvinChain gives (UA_Mod 3).
struct MinnemaPierceChain {
    double ds, alpha_filt, dalpha0, q, q_f, Kalpha_f, Kq, Kq_f;
    double k_alpha, T_alpha, T_q, T_f, T_V;
    double Kprime_alpha, cn_alpha_nc, Kprime_q, cn_q_nc, cn_aq_nc;
    double X1, X2, alpha_e, cn_aq_circ, K3prime_q, cm_q_circ, cn_pot, Kprimeprime_q, cm_q_nc;
    double cc_pot, Dp, cn_prime, alpha_f, fprime, Df, fprimeprime;
    double fprime_c, Df_c, fprimeprime_c, cn_fs, Dalphaf, C_V, cn_v;
    double cna_circ, T_I;
};
// The chains of one element's last two evaluations and their inputs (after UA's
// fixes) and dt: a step from the same state, input and dt (a simulation step's
// start is evaluated and then updated) takes its chain instead of computing it
// again; the step empties it, as the state changes.
struct MinnemaPierceMemo {
    struct Entry {
        UnsteadyInput u;
        double dt = 0;
        MinnemaPierceChain chain{};
        bool valid = false;
    };
    Entry entries[2];
    int next = 0;
};
UnsteadyOutput evaluate(const UnsteadyAirfoil& airfoil, const UnsteadySettings& settings,
                        double chord, double dt, const UnsteadyInput& u,
                        const MinnemaPierceState& state, MinnemaPierceMemo& memo);
UnsteadyOutput step(const UnsteadyAirfoil& airfoil, const UnsteadySettings& settings, double chord,
                    double dt, const UnsteadyInput& u, MinnemaPierceState& state,
                    MinnemaPierceMemo& memo);
// step() without its outputs: the state of t alone (AeroDyn's UpdateStates; the
// outputs at t are apply()'s evaluate of the same chain).
void advance(const UnsteadyAirfoil& airfoil, const UnsteadySettings& settings, double chord,
             double dt, const UnsteadyInput& u, MinnemaPierceState& state, MinnemaPierceMemo& memo);

// UA_Mod 6 state of one element: x4 (f, the separation point), FirstPass, and the
// derivative history of the multistep integrators (OtherState%xdot, %n).
struct OyeState {
    double x4 = 0;
    bool first_pass = true;
    long n = 0;                    // index of the next step (AeroDyn in OpenFAST starts at 0,
                                   // the UA driver at 1); RK4 while n <= 2
    long n_last = -1;              // step whose derivative xdot[0] holds
    double xdot[4] = {0, 0, 0, 0}; // dx4/dt at steps n, n-1, n-2, n-3
};

// Oye's x4 in steady flow at u: f_st(alpha_34) (HGM_Steady).
double oye_steady_x4(const UnsteadyAirfoil& airfoil, const UnsteadySettings& settings, double chord,
                     const UnsteadyInput& u);
// dx4/dt = (f_st(alpha_34) - x4) / (T_f0 Tu), Tu = c / (2 U).
double oye_derivative(const UnsteadyAirfoil& airfoil, const UnsteadySettings& settings,
                      double chord, const UnsteadyInput& u, double x4);
// Outputs for state x4 (the steady x4 while state.first_pass).
UnsteadyOutput evaluate(const UnsteadyAirfoil& airfoil, const UnsteadySettings& settings,
                        double chord, const UnsteadyInput& u, const OyeState& state);
// Advances x4 from t to t + dt with the inputs at t and t + dt (linear in between, as
// UA_Input_ExtrapInterp with two inputs); returns nothing: call evaluate() at each t.
void step(const UnsteadyAirfoil& airfoil, const UnsteadySettings& settings, double chord, double dt,
          const UnsteadyInput& u_t, const UnsteadyInput& u_next, OyeState& state);

} // namespace yamsc::aero
