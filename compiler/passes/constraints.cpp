// The constraint rows' derivatives (docs/theory.md, Constraint rows): B, ∂r/∂q,
// γ = ṙ - B q'' and the Jacobians of the constrained equations' extra terms,
// formed on the graph by forward mode. t is not a variable of the graph: its
// part of ṙ, r_t, comes from the derivation (through the inputs' derivative
// channels), so γ = (∂r/∂q) q' + r_t.
#include "diag/diagnostics.hpp"
#include "passes/forward.hpp"
#include "passes/pass_order.hpp"
#include "passes/passes.hpp"

namespace yamsc::passes {

using ir::NodeId;
using ir::Row;
using ir::SymbolKind;

namespace {

/// Σ_k weights[k] * nodes[k].
NodeId dot(ir::Graph& g, const Row& nodes, const Row& weights) {
    std::vector<ir::Operand> terms;
    for (std::size_t k = 0; k < nodes.size(); ++k)
        terms.push_back({g.mul({{nodes[k], 1.0}, {weights[k], 1.0}}, 1.0), 1.0});
    return g.add(std::move(terms), 0.0);
}

} // namespace

void constraint_derivatives(ir::System& s) {
    enter(s, ir::Pass::constraint_derivatives);
    ir::Graph& g = s.graph;
    const std::size_t nq = s.dofs.size(), nu = s.inputs.size(), nc = s.constraints.size();
    const NodeId zero = g.number(0.0);
    s.B.assign(nc, Row(nq, zero));
    s.dr_dq.assign(nc, Row(nq, zero));
    for (std::size_t k = 0; k < nq; ++k) {
        ForwardDerivative d_dq(g, k), d_dqd(g, nq + k);
        for (std::size_t i = 0; i < nc; ++i) {
            s.dr_dq[i][k] = d_dq(s.constraints[i].r);
            s.B[i][k] = d_dqd(s.constraints[i].r);
        }
    }
    Row qd, a, lambda;
    for (std::size_t k = 0; k < nq; ++k) {
        qd.push_back(g.symbol({SymbolKind::qd, static_cast<int>(k)}));
        a.push_back(g.symbol({SymbolKind::acceleration, static_cast<int>(k)}));
    }
    for (std::size_t i = 0; i < nc; ++i)
        lambda.push_back(g.symbol({SymbolKind::multiplier, static_cast<int>(i)}));
    s.gamma.clear();
    Row acc; // B a + γ
    for (std::size_t i = 0; i < nc; ++i) {
        const NodeId rate = dot(g, s.dr_dq[i], qd);
        s.gamma.push_back(g.add({{rate, 1.0}, {s.constraints[i].r_t, 1.0}}, 0.0));
        acc.push_back(g.add({{dot(g, s.B[i], a), 1.0}, {s.gamma[i], 1.0}}, 0.0));
    }
    Row BTl; // Bᵀ λ
    for (std::size_t k = 0; k < nq; ++k) {
        Row column;
        for (std::size_t i = 0; i < nc; ++i) column.push_back(s.B[i][k]);
        BTl.push_back(dot(g, column, lambda));
    }
    s.dBTl_dq.assign(nq, Row(nq, zero));
    s.dacc_dq.assign(nc, Row(nq, zero));
    s.dacc_dqd.assign(nc, Row(nq, zero));
    s.dBTl_du.assign(nq, Row(nu, zero));
    s.dacc_du.assign(nc, Row(nu, zero));
    for (std::size_t j = 0; j < nq; ++j) {
        ForwardDerivative d_dq(g, j), d_dqd(g, nq + j);
        for (std::size_t k = 0; k < nq; ++k) s.dBTl_dq[k][j] = d_dq(BTl[k]);
        for (std::size_t i = 0; i < nc; ++i) {
            s.dacc_dq[i][j] = d_dq(acc[i]);
            s.dacc_dqd[i][j] = d_dqd(acc[i]);
        }
    }
    for (std::size_t j = 0; j < nu; ++j) {
        ForwardDerivative d_du(g, 2 * nq + j);
        for (std::size_t k = 0; k < nq; ++k) s.dBTl_du[k][j] = d_du(BTl[k]);
        for (std::size_t i = 0; i < nc; ++i) s.dacc_du[i][j] = d_du(acc[i]);
    }
}

} // namespace yamsc::passes
