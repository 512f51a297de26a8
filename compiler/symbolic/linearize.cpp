#include "symbolic/linearize.hpp"

#include "diag/diagnostics.hpp"
#include "symbolic/dag.hpp"
#include "symbolic/expressions.hpp"
#include "symbolic/tape.hpp"

namespace yamsc::symbolic {

using namespace GiNaC;

OperatingPoint operating_point(const model::Model& m, const Equations& eq) {
    OperatingPoint op;
    op.q.assign(eq.dofs.size(), 0);
    op.qd.assign(eq.dofs.size(), 0);
    op.u.assign(eq.inputs.size(), 0);
    if (!m.operating_point) return op;
    const model::OperatingPoint& point = *m.operating_point;
    if (point.q.size() != op.q.size() || point.qd.size() != op.qd.size() ||
        point.u.size() != op.u.size() || m.params.size() != eq.params.size())
        throw diag::InternalError("the operating point does not match the equations");
    op.declared = true;
    // The values use parameters only. They are converted with symbols of their own
    // and then re-expressed in the symbols of `eq` (GiNaC symbols are identities,
    // not names).
    Symbols own(m);
    exmap to_eq;
    for (std::size_t i = 0; i < eq.params.size(); ++i)
        to_eq[own.params()[i].sym] = eq.params[i].sym;
    Substituter rename(to_eq);
    for (std::size_t i = 0; i < op.q.size(); ++i) op.q[i] = rename(to_ginac(point.q[i], own));
    for (std::size_t i = 0; i < op.qd.size(); ++i) op.qd[i] = rename(to_ginac(point.qd[i], own));
    for (std::size_t i = 0; i < op.u.size(); ++i) op.u[i] = rename(to_ginac(point.u[i], own));
    return op;
}

OutputJacobians output_jacobians(const Equations& eq) {
    const std::size_t nq = eq.dofs.size(), nu = eq.inputs.size(), ny = eq.outputs.size();
    OutputJacobians J;
    J.C.assign(ny, Row(2 * nq));
    J.D.assign(ny, Row(nu));
    // Forward mode on a Tape, as for the Jacobians of F: GiNaC's own products
    // would walk the shared kinematics as trees.
    std::vector<symbol> variables; // q (0..nq-1), q' (nq..2nq-1), u (2nq..)
    for (const Dof& d : eq.dofs) variables.push_back(d.q);
    for (const Dof& d : eq.dofs) variables.push_back(d.qd);
    for (const InputChannel& u : eq.inputs) variables.push_back(u.sym);
    Tape tape(variables);
    std::vector<TapeId> y;
    for (const Output& o : eq.outputs) y.push_back(tape.import(o.value));
    for (std::size_t k = 0; k < variables.size(); ++k) {
        ForwardDerivative d(tape, k);
        for (std::size_t i = 0; i < ny; ++i) {
            const ex dy = tape.to_ginac(d(y[i]));
            if (k < 2 * nq)
                J.C[i][k] = dy;
            else
                J.D[i][k - 2 * nq] = dy;
        }
    }
    return J;
}

} // namespace yamsc::symbolic
