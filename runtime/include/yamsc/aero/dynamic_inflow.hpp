#pragma once
// Dynamic inflow as AeroDyn's DBEMT module computes it (DBEMT_Mod 1, 2, 3): Øye's
// two first-order filters of the quasi-steady induced velocity of every blade
// element,
//   W_int + tau1 dW_int/dt = W_qs + k tau1 dW_qs/dt,    W + tau2 dW/dt = W_int,
// with k = 0.6, tau2 = (0.39 - 0.26 (r/R)^2) tau1 and tau1 either constant (DBEMT_Mod 1
// and 3) or 1.1 R / ((1 - 1.3 min(a_disk, 0.5)) U_disk) (DBEMT_Mod 2).
//
// Time structure as in AeroDyn: DBEMT_Mod 1 and 2 are discrete, update() advances the
// states from t to t + dt with the exact solution for a quasi-steady input varying
// linearly between its values at t and t + dt; DBEMT_Mod 3 has continuous states
// (W_red = W_int - k W_qs and W) whose derivative() a simulation integrates with the
// structure (update() integrates them alone with RK4, for a rigid rotor's time loop).
// Nothing here allocates after construction.
#include <cstddef>
#include <vector>

#include "yamsc/aero/rotor_input.hpp"

namespace yamsc::aero {

// Induced velocity of a blade element in AeroDyn's element frame [m/s]:
// axial = -a Vx, tangential = a' Vy (DBEMT's vind(1) and vind(2)).
struct InducedVelocity {
    double axial = 0, tangential = 0;
};

// Rotor-level inputs at one time (DBEMT's AxInd_disk, Un_disk, R_disk); used by
// DBEMT_Mod 2 only.
struct DbemtDiskInput {
    double axial_induction = 0; // kernel-weighted mean of the quasi-steady a [-]
    double normal_speed = 0;    // disk-averaged wind along the hub's x axis [m/s]
    double radius = 0;          // largest rlocal of every blade node at this time [m]
};

// Inputs at one time. Elements are blade-major: e = blade * nodes + node.
struct DbemtInput {
    DbemtDiskInput disk;
    std::vector<InducedVelocity> quasi_steady; // W_qs per element (vind_s)
    std::vector<double> rlocal; // distance from the rotor axis in the rotor plane [m] (DBEMT_Mod 2)
};

struct DbemtElementState {
    InducedVelocity vind;   // W, the filtered induced velocity (the output)
    InducedVelocity vind_1; // DBEMT_Mod 1, 2: W_int; DBEMT_Mod 3: W_red = W_int - k W_qs
};

struct DbemtState {
    std::vector<DbemtElementState> element;
    bool initialized = false; // false: the output is the quasi-steady input
    double tau1 = 0;          // tau1 of the last update [s] (AeroDyn's DBEMTau1)
};

struct InductionFactors {
    double axial = 0, tangential = 0; // a, a'
};

class Dbemt {
public:
    static constexpr double k_0ye = 0.6;                 // k of Øye's first filter
    static constexpr std::size_t states_per_element = 4; // W (axial, tangential), then vind_1

    // rlocal_init: every element's rlocal at the start (blade-major), for the constant
    // span ratios of DBEMT_Mod 1 and 3 and the weights of the disk-averaged induction.
    // dt: the step of update(). Throws std::invalid_argument on a bad value.
    Dbemt(DynamicInflow model, double tau1_const, double dt, int blades, int nodes,
          const std::vector<double>& rlocal_init);

    DynamicInflow model() const { return model_; }
    double dt() const { return dt_; }
    int blades() const { return blades_; }
    int nodes() const { return nodes_; }
    std::size_t elements() const { return span_ratio_.size(); }

    // Sized input and state (the only allocations: call them once).
    DbemtInput make_input() const;
    DbemtState make_state() const;

    // tau1 [s] for these disk inputs (ComputeTau1); tau2 / tau1 of element e (ComputeTau2).
    double tau1(const DbemtDiskInput& disk) const;
    double k_tau(const DbemtInput& u, std::size_t e) const;

    // The disk inputs from the quasi-steady axial inductions a (per element, limited,
    // zero where the BEM found no solution), the disk-averaged normal wind and the
    // current rlocal (SetInputs_For_DBEMT). Sets u.disk.
    void set_disk_input(DbemtInput& u, const double* a, double normal_speed) const;

    // States equal to the quasi-steady input, once (DBEMT_InitStates); no-op afterwards.
    void initialize(const DbemtInput& u, DbemtState& x) const;

    // States at t + dt from states at t and inputs at t and t + dt (DBEMT_UpdateStates).
    // Initializes x from u_t first if it is not. AeroDyn forms u_t from the inflow at
    // t + dt and the inductions at the inflow angle solved at the last step
    // (AD_UpdateStates, BEMT_UpdateStates), so a change of the wind falls between two
    // updates: DBEMT_Mod 1 and 2 (holding W_int) then miss the k jump of W_int that
    // DBEMT_Mod 3 (holding W_red) makes.
    void update(const DbemtInput& u_t, const DbemtInput& u_next, DbemtState& x) const;

    // The filtered induced velocity of element e (DBEMT_CalcOutput).
    InducedVelocity output(const DbemtInput& u, const DbemtState& x, std::size_t e) const {
        return x.initialized ? x.element[e].vind : u.quasi_steady[e];
    }

    // DBEMT_Mod 3: dx/dt on flat arrays of states_per_element values per element,
    // [W axial, W tangential, W_red axial, W_red tangential] (AeroDyn's linearization order).
    void derivative(const DbemtInput& u, const double* x, double* dxdt) const;
    static void pack(const DbemtState& x, double* flat);
    static void unpack(const double* flat, DbemtState& x);

private:
    void update_discrete(const DbemtInput& u_t, const DbemtInput& u_next, DbemtState& x) const;
    void update_rk4(const DbemtInput& u_t, const DbemtInput& u_next, DbemtState& x) const;

    DynamicInflow model_;
    double tau1_const_, dt_;
    int blades_, nodes_;
    std::vector<double> span_ratio_;  // rlocal_init / max rlocal_init
    std::vector<double> disk_weight_; // BEMT's IntegrateWeight
    double exp_tau1_ = 0;             // DBEMT_Mod 1, 3: exp(-dt / tau1)
    std::vector<double> exp_tau2_;    // DBEMT_Mod 1, 3: exp(-dt / tau2) per element
};

// Quasi-steady induced velocity from induction factors and the element's Vx, Vy
// (SetInputs_For_DBEMT), and the induction factors back from the filtered one, zero
// where the velocity is, limited as AeroDyn limits them (calculate_Inductions_from_DBEMT).
inline InducedVelocity induced_velocity(InductionFactors f, double vx, double vy) {
    return {-f.axial * vx, f.tangential * vy};
}
InductionFactors induction_factors(InducedVelocity w, double vx, double vy);

} // namespace yamsc::aero
