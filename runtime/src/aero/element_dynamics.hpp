#pragma once
// The unsteady parts of AeroDyn's BEMT on a BemRotor: dynamic inflow (DBEMT_Mod 1,
// 2, 3) and unsteady airfoil aerodynamics (UA_Mod 3, 6), with the states they
// hold, in the order BEMT_UpdateStates and BEMT_CalcOutput use them. Internal to
// the blade-element block (blade_element_block.cpp).
//
// Every state here is discrete in the block's sense (load_block.hpp): AeroDyn
// advances all of them once per time step inside UpdateStates, DBEMT_Mod 3 and
// UA_Mod 6 with their own integrators (RK4 for DBEMT here, UA's ABM4), so the
// structure's integrator never sees them.
#include "yamsc/aero/bem_rotor.hpp"
#include "yamsc/aero/dynamic_inflow.hpp"
#include "yamsc/aero/unsteady_airfoil.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace yamsc::aero {

class ElementDynamics {
public:
    explicit ElementDynamics(const RotorInput& input);

    /// Whether the rotor input asks for DBEMT or UA at all.
    bool active() const { return dbemt_on_ || ua_on_; }
    /// Whether apply() replaces every node's inductions and loads (DBEMT's, once
    /// started): the rotor's steady solve then needs only its roots and inductions.
    bool replaces_loads() const { return dbemt_ && x_.initialized; }
    /// Counts the changes of the states (each update changes them).
    std::uint64_t generation() const { return generation_; }

    /// The nodes of `rotor` (just solved quasi-steadily) with the filtered inductions
    /// and the unsteady coefficients of the current states; node_omega: each node's
    /// angular velocity (ground axes). Then the rotor's integrals again.
    void apply(BemRotor& rotor, const RotorMotion& motion,
               const std::vector<std::vector<Eigen::Vector3d>>& node_omega) const;

    /// One step from t to t + dt. `solve(at_next, wind_next, inputs_only)` evaluates
    /// the rotor quasi-steadily with the motion of t (at_next false) or t + dt, and
    /// the wind of t + dt (wind_next true) or of its own time (with inputs_only,
    /// only its nodes' element inputs: BemRotor::element_inputs), and returns it
    /// together with the node angular velocities it filled.
    struct Solved {
        BemRotor* rotor;
        const RotorMotion* motion;
        const std::vector<std::vector<Eigen::Vector3d>>* node_omega;
    };
    template <class Solve> void update(double dt, bool wind_changes, Solve&& solve);

    /// Back to the start of a run: no state, so apply() is quasi-steady (the
    /// polar, the quasi-steady induction) until the next update.
    void reset();

private:
    void sample(const RotorResult& r, DbemtInput& u, bool stale_phi);
    void unsteady_inputs(const RotorResult& r,
                         const std::vector<std::vector<Eigen::Vector3d>>& node_omega,
                         std::vector<UnsteadyInput>& u) const;
    void start_dbemt(const RotorResult& r, double dt);
    void step_unsteady(double interval);
    void locate_ua_span(const RotorResult& r) const;
    bool ua_node(std::size_t blade, std::size_t node) const;

    const RotorInput& input_;
    BemOptions options_;
    bool dbemt_on_ = false, ua_on_ = false;
    // DBEMT (made at the first step, when dt and the radii are known).
    std::optional<Dbemt> dbemt_;
    DbemtInput u_t_, u_next_;
    DbemtState x_;
    std::vector<ElementSolution> phi_; // AeroDyn's z%phi: the last step's solve
    std::vector<double> a_qs_;
    bool have_next_ = false;
    // UA: one table per airfoil, state per element (blade-major).
    UnsteadySettings ua_settings_;
    std::vector<std::optional<UnsteadyAirfoil>> ua_airfoils_;
    // Per blade, found at the first evaluation: UA off for nodes <= inner, >= outer (1-based).
    mutable std::vector<int> ua_inner_, ua_outer_;
    std::vector<MinnemaPierceState> mp_;
    mutable std::vector<MinnemaPierceMemo> mp_memo_; // the chains apply computed
    std::vector<OyeState> oye_;
    std::vector<UnsteadyInput> ua_t_, ua_next_;
    double ua_dt_ = 0; // UA's step, AeroDyn's p%dt (step_unsteady)
    long step_ = 0;    // AeroDyn's n of the next update
    // Counts the changes of the states apply reads (RotorCache's generation).
    std::uint64_t generation_ = 0;
    mutable std::vector<double> omega_key_;
};

template <class Solve> void ElementDynamics::update(double dt, bool wind_changes, Solve&& solve) {
    // BEMT_UpdateStates: UA's inputs at t with DBEMT's output at t ...
    if (ua_on_) {
        const Solved s = solve(false, false, false);
        apply(*s.rotor, *s.motion, *s.node_omega);
        unsteady_inputs(s.rotor->result(), *s.node_omega, ua_t_);
    }
    // ... DBEMT from its inputs at t and t + dt (both with the wind of t + dt) ...
    if (dbemt_on_) {
        if (!dbemt_ || !have_next_ || wind_changes) {
            // After the first step DBEMT's input at t takes the last step's inflow
            // angle (sample's stale_phi), so the element inputs are enough.
            const Solved s = solve(false, true, have_next_);
            if (!dbemt_) start_dbemt(s.rotor->result(), dt);
            sample(s.rotor->result(), u_t_, have_next_);
        } else {
            std::swap(u_t_, u_next_);
        }
        const Solved s = solve(true, true, false);
        sample(s.rotor->result(), u_next_, false);
        have_next_ = true;
        dbemt_->update(u_t_, u_next_, x_);
        ++generation_;
    }
    // ... then UA from its inputs at t (UA_Mod 3) or t and t + dt (UA_Mod 6, whose
    // inputs at t + dt see DBEMT's new output).
    if (ua_on_) {
        if (ua_settings_.model == UnsteadyModel::oye) {
            const Solved s = solve(true, true, false);
            apply(*s.rotor, *s.motion, *s.node_omega);
            unsteady_inputs(s.rotor->result(), *s.node_omega, ua_next_);
        }
        step_unsteady(dt);
    }
    ++step_;
}

} // namespace yamsc::aero
