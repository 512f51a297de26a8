#pragma once
// Load blocks: whatever computes loads on a model from its motion and time (the
// quasi-steady rotor table of rotor_aero.hpp; blade elements, wind fields,
// hydrodynamics and mooring alike). A block reads some of the model's outputs
// (its motion: speeds, velocities, positions) and inputs (wind, pitch), has
// states of its own if it needs them, and adds its loads to input channels of
// the model; close_blocks() feeds them back, so the closed view is again a
// ModelView that every integrator, `lin` and `trim` take as they take a model.
//
// Two kinds of states, as OpenFAST's modules have them:
// - continuous states z (state_names, evaluate's rates): integrated with the
//   structure, at every stage of every step;
// - discrete states, held by the block itself (has_discrete_states,
//   update_discrete_states): constant within a step, so every stage of the step
//   sees the values of its start, and advanced once per accepted step from the
//   values the block reads at t and at t + dt (AeroDyn's UpdateStates: UA and
//   DBEMT, whose continuous models, UA_Mod 6 and DBEMT_Mod 3, AeroDyn also
//   advances there with their own integrators). The fixed-step integrators (RK4, ABM4)
//   call ModelView::update_discrete after each step; simulate() with CVODE calls
//   it between output points (the output step is then the discrete step).
//   A block with discrete states belongs to one simulation at a time.
#include "yamsc/model_view.hpp"

#include <memory>
#include <string>
#include <vector>

namespace yamsc::runtime {

/// Where a block meets the view it is closed around, as indices of its channels.
struct BlockPorts {
    std::vector<int> outputs_read; // the view's outputs the block reads
    std::vector<int> inputs_read;  // the view's inputs it reads; -1: an absent optional one (0)
    std::vector<int> loads;        // the inputs its loads are added to, one per load
};

/// Partial derivatives of a block's loads and state rates, row-major: rows are
/// loads (or rates), columns the block's states z or the values r it reads,
/// r = [outputs read, inputs read] in the order of its ports.
struct BlockJacobian {
    std::vector<double> loads_z, loads_r, rates_z, rates_r;
};

class LoadBlock {
public:
    virtual ~LoadBlock() = default;
    virtual const BlockPorts& ports() const = 0;
    /// Its own outputs, appended to the view's.
    virtual std::vector<std::string> output_names() const = 0;
    /// Its states, integrated with the model's (none unless it has some).
    virtual std::vector<std::string> state_names() const { return {}; }
    virtual std::vector<double> initial_states() const;
    /// The loads (one per port load), the state rates z' and the block's outputs
    /// at time t, states z and read values r. May throw std::invalid_argument.
    virtual void evaluate(double t, const double* z, const double* r, double* loads, double* rates,
                          double* out) const = 0;
    /// d(loads, z')/d(z, r); central differences of evaluate unless the block
    /// knows them exactly.
    virtual void derivatives(double t, const double* z, const double* r, BlockJacobian& j) const;
    /// Whether it holds discrete states (then closed views call update_discrete_states).
    virtual bool has_discrete_states() const { return false; }
    /// Advances its discrete states from t to t_next, once per accepted step,
    /// from its states z and read values r at both times (AeroDyn's
    /// UpdateStates(t, n, u(t), u(t + dt))). evaluate() then uses the new ones.
    virtual void update_discrete_states(double /*t*/, const double* /*z*/, const double* /*r*/,
                                        double /*t_next*/, const double* /*z_next*/,
                                        const double* /*r_next*/) const {}
    /// Forgets its discrete states, as at the start of a run (trim settles them
    /// at its point from there).
    virtual void reset_discrete_states() const {}

    /// Whether its loads also depend on the model's accelerations, linearly (a
    /// fluid's added mass): then the loads applied are evaluate()'s minus
    /// A (G^T q''), where G (nq x nl) is how the model applies the block's loads
    /// (dF/d(load inputs): for a force and moment at a body's origin in body
    /// axes, G^T q'' is that origin's acceleration and the body's angular
    /// acceleration in body axes, without the terms in the rates). close_blocks()
    /// solves for them with the structure, as OpenFAST's glue code solves
    /// ElastoDyn's and HydroDyn's inputs and outputs together: the closed view's
    /// mass matrix is M + G A G^T, so `lin` sees the added mass.
    virtual bool has_added_mass() const { return false; }
    /// A (nl x nl, row-major) at time t, states z and read values r.
    virtual void added_mass(double /*t*/, const double* /*z*/, const double* /*r*/,
                            double* /*A*/) const {}
};

/// LoadBlock::derivatives' central differences of `block.evaluate`, each value
/// v stepped by relative_step (1 + |v|) either way (the default: 1e-6).
void central_differences(const LoadBlock& block, double t, const double* z, const double* r,
                         BlockJacobian& j, double relative_step);

using LoadBlocks = std::vector<std::shared_ptr<const LoadBlock>>;

/// How a closed view meets its blocks within a step of a fixed-step integrator.
/// - tight: every stage evaluates the blocks at its own state (the integrator's
///   order holds for the loads too); `lin`, `trim` and CVODE always couple so.
/// - loose: OpenFAST's glue code with ModCoupling 1. The blocks are evaluated once
///   per accepted step, at its end (after their discrete update, as AeroDyn's
///   CalcOutput follows its UpdateStates), and a stage within the next step takes
///   their loads and outputs extrapolated from the last interp_order + 1 steps'
///   (InterpOrder: 0 holds them, 1 linear, 2 quadratic), as ElastoDyn takes
///   AeroDyn's loads through ED_Input_ExtrapInterp. A stage at a step's own time
///   (ABM4's and RK4's first) takes that step's values. Only for blocks without
///   continuous states; the history belongs to the view, so a loosely coupled
///   view runs one simulation at a time (as its blocks' discrete states do).
enum class Coupling { tight, loose };
struct BlockCoupling {
    Coupling mode = Coupling::tight;
    int interp_order = 2;
};

/// `base` with the blocks closed around it, in order: each around the view
/// closed by those before it (its ports are indices of that view, whose outputs
/// end with theirs). Same DOFs and inputs; outputs followed by each block's;
/// states [q, q', z of the first block, z of the second, ...] (ModelView::nz).
/// Jacobians: the base's plus the chain rule through the loads (the block's
/// derivatives; those of the outputs it reads by central differences of the
/// base's outputs, read without q'' when the base has outputs_from_qdd).
/// A closed view with states has rhs, rhs_jacobian, mass_matrix and outputs
/// (it is integrated, not linearized): no forcing or jacobians.
/// update_discrete: the blocks' in order (inner first), each reading the view
/// it is closed around with the model's inputs (not the loads of the blocks
/// closed after it); set when any block has discrete states.
/// coupling: loose (above) for a simulation with RK4 or ABM4; the Jacobians of
/// a loosely coupled view are still those of the tight one.
ModelView close_blocks(const ModelView& base, const LoadBlocks& blocks,
                       BlockCoupling coupling = {});

} // namespace yamsc::runtime
