// Exact Jacobians of F and of M(q) a by forward mode: each derivative node is
// built once per variable, so the Jacobians stay DAGs over the kinematics
// instead of growing as copies of F.
#include "diag/diagnostics.hpp"
#include "passes/forward.hpp"
#include "passes/pass_order.hpp"
#include "passes/passes.hpp"

namespace yamsc::passes {

using ir::NodeId;
using ir::Row;
using ir::SymbolKind;

void derive_jacobians(ir::System& s) {
    enter(s, ir::Pass::derive_jacobians);
    ir::Graph& g = s.graph;
    const std::size_t nq = s.dofs.size(), nu = s.inputs.size();
    if (s.F.size() != nq || (s.Ma.empty() && s.M.size() != nq))
        throw diag::InternalError("the Jacobians need F and M (or M a)");
    if (s.Ma.empty()) {
        for (std::size_t r = 0; r < nq; ++r) {
            std::vector<ir::Operand> terms;
            for (std::size_t c = 0; c < nq; ++c) {
                const NodeId a = g.symbol({SymbolKind::acceleration, static_cast<int>(c)});
                terms.push_back({g.mul({{s.M[r][c], 1.0}, {a, 1.0}}, 1.0), 1.0});
            }
            s.Ma.push_back(g.add(std::move(terms), 0.0));
        }
    }
    const NodeId zero = g.number(0.0);
    s.dF_dq.assign(nq, Row(nq, zero));
    s.dF_dqd.assign(nq, Row(nq, zero));
    s.dF_du.assign(nq, Row(nu, zero));
    s.dMa_dq.assign(nq, Row(nq, zero));
    // Variables: q (0..nq-1), q' (nq..2nq-1), u (2nq..).
    for (std::size_t k = 0; k < nq; ++k) {
        ForwardDerivative d_dq(g, k);
        for (std::size_t r = 0; r < nq; ++r) s.dF_dq[r][k] = d_dq(s.F[r]);
        for (std::size_t r = 0; r < nq; ++r) s.dMa_dq[r][k] = d_dq(s.Ma[r]);
        ForwardDerivative d_dqd(g, nq + k);
        for (std::size_t r = 0; r < nq; ++r) s.dF_dqd[r][k] = d_dqd(s.F[r]);
    }
    for (std::size_t k = 0; k < nu; ++k) {
        ForwardDerivative d_du(g, 2 * nq + k);
        for (std::size_t r = 0; r < nq; ++r) s.dF_du[r][k] = d_du(s.F[r]);
    }
}

} // namespace yamsc::passes
