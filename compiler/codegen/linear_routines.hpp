#pragma once
// The routines of the linear model (docs/linearization.md): `linear` (M0, C0, K0,
// Q0 of eq. 25), `state_space` (A, B), `output_matrices` (C, D), all functions
// of an operating point (q0, q0', u0) given as arguments and of the parameters
// (LPV), and `operating_point` (the model's `linearize` block as a function of
// the parameters). They are built from the same canonical Graph as the other
// routines, so they get the same CSE and deterministic output.
#include "codegen/module.hpp"

#include <vector>

namespace yamsc::codegen {

/// The imported nodes of the nonlinear equations the linear routines reuse.
struct LinearSources {
    const std::vector<std::vector<NodeId>>& M;
    const std::vector<NodeId>& F;
    const std::vector<std::vector<NodeId>>& dF_dq;
    const std::vector<std::vector<NodeId>>& dF_dqd;
    const std::vector<std::vector<NodeId>>& dF_du;
    const std::vector<std::vector<NodeId>>& dMa_dq;
};

/// Appends linear, state_space and output_matrices (from s.C and s.D) to `routines`.
void add_linear_routines(Graph& graph, const ir::System& s, const LinearSources& in,
                         const Options& options, std::vector<Routine>& routines);

/// Appends `operating_point(p, q0, qd0, u0)` to the module: the System's point
/// (all zeros without a `linearize` block).
void add_operating_point(Module& module, const ir::System& s);

} // namespace yamsc::codegen
