#include "symbolic/linearize.hpp"

#include "diag/diagnostics.hpp"
#include "symbolic/dag.hpp"
#include "symbolic/expressions.hpp"

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

} // namespace yamsc::symbolic
