#include "symbolic/dag.hpp"
#include "symbolic/derive.hpp"

namespace yamsc::symbolic {

using namespace GiNaC;

void derive_jacobians(Equations& eq) {
    const std::size_t nq = eq.dofs.size(), nu = eq.inputs.size();
    eq.dF_dq.assign(nq, Row(nq, 0));
    eq.dF_dqd.assign(nq, Row(nq, 0));
    eq.dF_du.assign(nq, Row(nu, 0));
    eq.dMa_dq.assign(nq, Row(nq, 0));
    eq.a.clear();
    for (std::size_t s = 0; s < nq; ++s) eq.a.emplace_back("a_" + eq.dofs[s].name);
    std::vector<ex> Ma(nq);
    for (std::size_t r = 0; r < nq; ++r) {
        exvector terms;
        for (std::size_t s = 0; s < nq; ++s) terms.push_back(eq.M[r][s] * eq.a[s]);
        Ma[r] = add(terms);
    }
    for (std::size_t k = 0; k < nq; ++k) {
        Differentiator dq(eq.dofs[k].q), dqd(eq.dofs[k].qd);
        for (std::size_t r = 0; r < nq; ++r) {
            eq.dF_dq[r][k] = dq(eq.F[r]);
            eq.dF_dqd[r][k] = dqd(eq.F[r]);
            eq.dMa_dq[r][k] = dq(Ma[r]);
        }
    }
    for (std::size_t k = 0; k < nu; ++k) {
        Differentiator du(eq.inputs[k].sym);
        for (std::size_t r = 0; r < nq; ++r) eq.dF_du[r][k] = du(eq.F[r]);
    }
}

} // namespace yamsc::symbolic
