#include "element_dynamics.hpp"

#include "yamsc/aero/dynamic_inflow_element.hpp"
#include "yamsc/aero/polar.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::aero {

ElementDynamics::ElementDynamics(const RotorInput& input)
    : input_(input), options_(bem_options(input)) {
    dbemt_on_ = input.wake == WakeModel::bem && input.dynamic_inflow != DynamicInflow::none;
    ua_on_ = input.unsteady != UnsteadyModel::none;
    if (ua_on_ && input.unsteady != UnsteadyModel::minnema_pierce &&
        input.unsteady != UnsteadyModel::oye)
        throw std::invalid_argument("blade elements: UA_Mod " +
                                    std::to_string(static_cast<int>(input.unsteady)) +
                                    " is not supported (0, 3 or 6)");
    if (!ua_on_) return;
    ua_settings_ = unsteady_settings(input);
    // Only the airfoils the blades use: a table without UA constants may sit unused.
    ua_airfoils_.resize(input.airfoils.size());
    std::size_t elements = 0;
    for (const auto& blade : input.blades) {
        elements += blade.size();
        for (const BladeNode& n : blade) {
            auto& af = ua_airfoils_[static_cast<std::size_t>(n.airfoil)];
            if (!af) af.emplace(input.airfoils[static_cast<std::size_t>(n.airfoil)]);
        }
    }
    mp_.assign(elements, MinnemaPierceState{});
    mp_memo_.assign(elements, MinnemaPierceMemo{});
    oye_.assign(elements, OyeState{});
    ua_t_.resize(elements);
    ua_next_.resize(elements);
}

void ElementDynamics::reset() {
    dbemt_.reset();
    u_t_ = {};
    u_next_ = {};
    x_ = {};
    phi_.clear();
    a_qs_.clear();
    have_next_ = false;
    mp_.assign(mp_.size(), MinnemaPierceState{});
    mp_memo_.assign(mp_memo_.size(), MinnemaPierceMemo{});
    oye_.assign(oye_.size(), OyeState{});
    ua_dt_ = 0;
    step_ = 0;
    ++generation_; // what apply kept belongs to the old states
}

void ElementDynamics::locate_ua_span(const RotorResult& r) const {
    // UAStartRad, UAEndRad: UA off for good from the root to the last node inside
    // the start and from the first node beyond the end (AeroDyn's UAOff_innerNode,
    // UAOff_outerNode, from the radii at the start over the largest of them).
    double r_max = 0;
    for (const auto& blade : r.blades)
        for (const auto& node : blade) r_max = std::max(r_max, node.r_local);
    ua_inner_.assign(r.blades.size(), 0);
    ua_outer_.assign(r.blades.size(), 0);
    for (std::size_t k = 0; k < r.blades.size(); ++k) {
        ua_outer_[k] = static_cast<int>(r.blades[k].size()) + 1;
        for (std::size_t j = 0; j < r.blades[k].size(); ++j) {
            const double frac = r.blades[k][j].r_local / r_max;
            const int node = static_cast<int>(j) + 1;
            if (frac < input_.ua_start_radius)
                ua_inner_[k] = std::max(ua_inner_[k], node);
            else if (frac > input_.ua_end_radius)
                ua_outer_[k] = std::min(ua_outer_[k], node);
        }
    }
}

bool ElementDynamics::ua_node(std::size_t blade, std::size_t node) const {
    const int j = static_cast<int>(node) + 1;
    if (j <= ua_inner_[blade] || j >= ua_outer_[blade]) return false;
    const BladeNode& n = input_.blades[blade][node];
    return ua_airfoils_[static_cast<std::size_t>(n.airfoil)]->supports(ua_settings_.model);
}

void ElementDynamics::apply(BemRotor& rotor, const RotorMotion& motion,
                            const std::vector<std::vector<Eigen::Vector3d>>& node_omega) const {
    omega_key_.clear();
    for (const auto& blade : node_omega)
        for (const Eigen::Vector3d& w : blade)
            omega_key_.insert(omega_key_.end(), w.data(), w.data() + 3);
    if (rotor.recall_applied(generation_, omega_key_)) return;
    auto& blades = rotor.nodes();
    if (!replaces_loads() && !rotor.result().loads) rotor.complete_loads(motion);
    if (ua_on_ && ua_inner_.empty()) locate_ua_span(rotor.result());
    const double rho = input_.air_density;
    std::size_t e = 0;
    for (std::size_t k = 0; k < blades.size(); ++k)
        for (std::size_t j = 0; j < blades[k].size(); ++j, ++e) {
            NodeResult& n = blades[k][j];
            // calculate_Inductions_from_DBEMT, then the skew correction and the
            // low-TSR blend on the filtered induction.
            const bool unsteady = ua_on_ && ua_node(k, j);
            if (replaces_loads()) {
                const InductionFactors f =
                    filtered_induction(*dbemt_, u_next_, x_, e, n.input, options_, n.bem);
                n.bem = element_with_induction(n.input, options_, rho, f, n.bem,
                                               unsteady ? ElementCoefficients::set_by_caller
                                                        : ElementCoefficients::polar);
            }
            if (!unsteady) continue;
            // BEMT_CalcOutput with UA: the coefficients of UA_CalcOutput at the
            // element's inputs of this time.
            UnsteadyInput u;
            const double a = n.bem.alpha, U = n.bem.vrel;
            u.alpha = a;
            u.U = U;
            u.v_ac_n = U * std::sin(a);
            u.v_ac_c = U * std::cos(a);
            u.omega = node_omega[k][j].dot(n.z);
            const UnsteadyAirfoil& af =
                *ua_airfoils_[static_cast<std::size_t>(input_.blades[k][j].airfoil)];
            const UnsteadyOutput y =
                ua_settings_.model == UnsteadyModel::oye
                    ? evaluate(af, ua_settings_, n.input.chord, u, oye_[e])
                    : evaluate(af, ua_settings_, n.input.chord, ua_dt_, u, mp_[e], mp_memo_[e]);
            set_coefficients(n.bem, {y.cl, y.cd, y.cm}, n.input.chord, rho, options_);
        }
    rotor.integrate(motion);
    rotor.keep_applied(generation_, omega_key_);
}

void ElementDynamics::unsteady_inputs(const RotorResult& r,
                                      const std::vector<std::vector<Eigen::Vector3d>>& node_omega,
                                      std::vector<UnsteadyInput>& u) const {
    // SetInputs_for_UA: alpha and U of the element with its inductions, v_ac from
    // them, omega the node's rotation about the element's z axis (omega_z).
    std::size_t e = 0;
    for (std::size_t k = 0; k < r.blades.size(); ++k)
        for (std::size_t j = 0; j < r.blades[k].size(); ++j, ++e) {
            const NodeResult& n = r.blades[k][j];
            const double a = n.bem.alpha, U = n.bem.vrel;
            u[e] = {U, a, node_omega[k][j].dot(n.z), U * std::sin(a), U * std::cos(a)};
        }
}

void ElementDynamics::start_dbemt(const RotorResult& r, double dt) {
    std::vector<double> rlocal;
    for (const auto& blade : r.blades)
        for (const auto& node : blade) rlocal.push_back(node.r_local);
    dbemt_.emplace(input_.dynamic_inflow, input_.tau1_const, dt, static_cast<int>(r.blades.size()),
                   static_cast<int>(r.blades.front().size()), rlocal);
    u_t_ = dbemt_->make_input();
    u_next_ = dbemt_->make_input();
    x_ = dbemt_->make_state();
    phi_.assign(rlocal.size(), ElementSolution{});
    a_qs_.assign(rlocal.size(), 0.0);
}

void ElementDynamics::sample(const RotorResult& r, DbemtInput& u, bool stale_phi) {
    // SetInputs_For_DBEMT from the inductions at the inflow angle: AeroDyn's input
    // at t takes the angle solved at the last step (z%phi), the one at t + dt its own.
    std::size_t e = 0;
    for (const auto& blade : r.blades)
        for (const auto& node : blade) {
            // The solve's own inductions at its root, or those of the last step's root.
            if (!stale_phi) phi_[e] = node.bem;
            const InductionFactors f = stale_phi
                                           ? quasi_steady_induction(node.input, options_, phi_[e])
                                           : InductionFactors{node.bem.a_bem, node.bem.ap_bem};
            u.quasi_steady[e] = induced_velocity(f, node.vx, node.vy);
            u.rlocal[e] = node.r_local;
            a_qs_[e++] = f.axial;
        }
    dbemt_->set_disk_input(u, a_qs_.data(), r.v_avg_xh);
}

void ElementDynamics::step_unsteady(double interval) {
    // UA steps by AeroDyn's p%dt, the coupling interval: the first step's length,
    // whatever the last bits of a later t_next - t (the chain apply() evaluated at
    // the step's start, the memo, is then the one the update takes). A step that
    // differs by more than round-off (another step size) steps by its own length;
    // the round-off of t + dt - t stays below 1e-6 of dt while t < 1e9 dt.
    if (ua_dt_ == 0 || std::abs(interval - ua_dt_) > 1e-6 * ua_dt_) ua_dt_ = interval;
    const double dt = ua_dt_;
    ++generation_;
    std::size_t e = 0;
    for (std::size_t k = 0; k < input_.blades.size(); ++k)
        for (std::size_t j = 0; j < input_.blades[k].size(); ++j, ++e) {
            if (!ua_node(k, j)) continue;
            const UnsteadyAirfoil& af =
                *ua_airfoils_[static_cast<std::size_t>(input_.blades[k][j].airfoil)];
            const double chord = input_.blades[k][j].chord;
            if (ua_settings_.model == UnsteadyModel::oye)
                step(af, ua_settings_, chord, dt, ua_t_[e], ua_next_[e], oye_[e]);
            else if (step_ > 0) // UA_UpdateStates leaves UA_Mod 3 alone at n = 0
                advance(af, ua_settings_, chord, dt, ua_t_[e], mp_[e], mp_memo_[e]);
        }
}

} // namespace yamsc::aero
