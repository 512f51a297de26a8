// The tangent form of the derivatives: one directional derivative of
// G = F - M a (a held) and of the outputs along symbolic seeds
// [dq, dq', du], instead of 2 nq + nu unrolled Jacobian columns. Its size is
// that of F, M a and the outputs (a few times over), so a 40-link chain costs
// O(n²) nodes here where the unrolled Jacobians cost O(n³).
#include "diag/diagnostics.hpp"
#include "symbolic/derive.hpp"
#include "symbolic/tape.hpp"

namespace yamsc::symbolic {

using namespace GiNaC;

void derive_tangent(Equations& eq) {
    const std::size_t nq = eq.dofs.size();
    if (eq.Ma.size() != nq || eq.a.size() != nq)
        throw diag::InternalError("the tangent form needs M a assembled by derive()");

    // Variables: q (0..nq-1), q' (nq..2nq-1), u (2nq..), seeded in that order.
    std::vector<symbol> variables;
    eq.seed.clear();
    for (const Dof& d : eq.dofs) {
        variables.push_back(d.q);
        eq.seed.emplace_back("d_" + d.name);
    }
    for (const Dof& d : eq.dofs) {
        variables.push_back(d.qd);
        eq.seed.emplace_back("d_" + d.name + "_dot");
    }
    for (const InputChannel& u : eq.inputs) {
        variables.push_back(u.sym);
        eq.seed.emplace_back("d_" + u.name);
    }
    Tape tape(variables);
    std::vector<TapeId> seeds;
    for (const symbol& s : eq.seed) seeds.push_back(tape.import(s));
    ForwardDerivative along(tape, seeds);

    eq.dG.assign(nq, 0);
    for (std::size_t r = 0; r < nq; ++r) {
        const TapeId G = tape.add({{tape.import(eq.F[r]), 1.0}, {tape.import(eq.Ma[r]), -1.0}});
        eq.dG[r] = tape.to_ginac(along(G));
    }
    eq.dY.assign(eq.outputs.size(), 0);
    for (std::size_t i = 0; i < eq.outputs.size(); ++i)
        eq.dY[i] = tape.to_ginac(along(tape.import(eq.outputs[i].value)));
    eq.tangent_form = true;
}

} // namespace yamsc::symbolic
