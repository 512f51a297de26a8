// Exact Jacobians of F and of M(q) a by forward-mode differentiation on a Tape
// (symbolic/tape.hpp): each derivative node is built once per variable and
// shares everything it can with F, M and the other derivatives, so the
// Jacobians stay DAGs over the kinematics instead of growing as copies of F.
#include "symbolic/derive.hpp"
#include "symbolic/tape.hpp"

namespace yamsc::symbolic {

using namespace GiNaC;

void derive_jacobians(Equations& eq) {
    const std::size_t nq = eq.dofs.size(), nu = eq.inputs.size();
    eq.dF_dq.assign(nq, Row(nq, 0));
    eq.dF_dqd.assign(nq, Row(nq, 0));
    eq.dF_du.assign(nq, Row(nu, 0));
    eq.dMa_dq.assign(nq, Row(nq, 0));
    if (eq.Ma.empty()) {
        eq.a.clear();
        for (std::size_t s = 0; s < nq; ++s) eq.a.emplace_back("a_" + eq.dofs[s].name);
    }

    // Variables: q (0..nq-1), q' (nq..2nq-1), u (2nq..).
    std::vector<symbol> variables;
    for (const Dof& d : eq.dofs) variables.push_back(d.q);
    for (const Dof& d : eq.dofs) variables.push_back(d.qd);
    for (const InputChannel& u : eq.inputs) variables.push_back(u.sym);
    Tape tape(variables);

    std::vector<TapeId> F(nq), Ma(nq);
    for (std::size_t r = 0; r < nq; ++r) F[r] = tape.import(eq.F[r]);
    std::vector<TapeId> a(nq);
    for (std::size_t s = 0; s < nq; ++s) a[s] = tape.import(eq.a[s]);
    for (std::size_t r = 0; r < nq && !eq.Ma.empty(); ++r) Ma[r] = tape.import(eq.Ma[r]);
    for (std::size_t r = 0; r < nq && eq.Ma.empty(); ++r) {
        std::vector<TapeTerm> terms;
        for (std::size_t s = 0; s < nq; ++s)
            terms.push_back({tape.mul({{tape.import(eq.M[r][s]), 1.0}, {a[s], 1.0}}), 1.0});
        Ma[r] = tape.add(std::move(terms));
    }

    auto column = [&](ForwardDerivative& d, const std::vector<TapeId>& f, Matrix& out,
                      std::size_t k) {
        for (std::size_t r = 0; r < nq; ++r) out[r][k] = tape.to_ginac(d(f[r]));
    };
    for (std::size_t k = 0; k < nq; ++k) {
        ForwardDerivative d_dq(tape, k);
        column(d_dq, F, eq.dF_dq, k);
        column(d_dq, Ma, eq.dMa_dq, k);
        ForwardDerivative d_dqd(tape, nq + k);
        column(d_dqd, F, eq.dF_dqd, k);
    }
    for (std::size_t k = 0; k < nu; ++k) {
        ForwardDerivative d_du(tape, 2 * nq + k);
        column(d_du, F, eq.dF_du, k);
    }
}

} // namespace yamsc::symbolic
