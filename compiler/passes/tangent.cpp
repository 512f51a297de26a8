// The tangent form of the derivatives: one directional derivative of
// G = F - M a (a held) and of the outputs along the seed symbols
// [dq, dq', du], instead of 2 nq + nu unrolled Jacobian columns. Its size is
// that of F, M a and the outputs (a few times over), so a 40-link chain costs
// O(n²) nodes here where the unrolled Jacobians cost O(n³).
#include "diag/diagnostics.hpp"
#include "passes/forward.hpp"
#include "passes/pass_order.hpp"
#include "passes/passes.hpp"

namespace yamsc::passes {

using ir::NodeId;

void derive_tangent(ir::System& s) {
    enter(s, ir::Pass::derive_tangent);
    ir::Graph& g = s.graph;
    const std::size_t nq = s.dofs.size(), nu = s.inputs.size();
    if (s.Ma.size() != nq || s.F.size() != nq)
        throw diag::InternalError("the tangent form needs M a assembled by derive()");
    if (s.outputs_read_accelerations())
        throw diag::InternalError("the tangent form has no M to solve the outputs' q'' with");
    // Seed k for variable k: q (0..nq-1), q' (nq..2nq-1), u (2nq..); none for p.
    std::vector<NodeId> seeds(static_cast<std::size_t>(g.variables().count()), g.number(0.0));
    for (std::size_t k = 0; k < 2 * nq + nu; ++k)
        seeds[k] = g.symbol({ir::SymbolKind::seed, static_cast<int>(k)});
    ForwardDerivative along(g, std::move(seeds));
    s.dG.clear();
    for (std::size_t r = 0; r < nq; ++r)
        s.dG.push_back(along(g.add({{s.F[r], 1.0}, {s.Ma[r], -1.0}}, 0.0)));
    s.dY.clear();
    for (const ir::Output& y : s.outputs) s.dY.push_back(along(y.value));
    s.tangent_form = true;
}

} // namespace yamsc::passes
