// The externals' arguments: separated from the outputs after lowering, and
// differentiated like outputs (forward mode, one pass per variable).
#include "diag/diagnostics.hpp"
#include "passes/forward.hpp"
#include "passes/pass_order.hpp"
#include "passes/passes.hpp"

namespace yamsc::passes {

using ir::Matrix;
using ir::NodeId;
using ir::Row;

void separate_externals(ir::System& s) {
    enter(s, ir::Pass::separate_externals);
    std::size_t nargs = 0;
    for (const ir::External& e : s.externals) nargs += e.args.size();
    if (nargs > s.outputs.size())
        throw diag::InternalError("the externals' arguments are missing from the outputs");
    std::size_t next = s.outputs.size() - nargs;
    for (ir::External& e : s.externals) {
        for (NodeId& a : e.args) {
            const ir::Output& y = s.outputs[next++];
            if (!y.dqdd.empty())
                throw diag::InternalError("an argument of an external reads accelerations");
            a = y.value;
        }
    }
    s.outputs.resize(s.outputs.size() - nargs);
    const auto declared = static_cast<std::size_t>(s.declared_nu());
    if (s.point.u.size() > declared) s.point.u.resize(declared);
}

void external_jacobians(ir::System& s) {
    enter(s, ir::Pass::external_jacobians);
    const std::size_t nq = s.dofs.size(), nu = static_cast<std::size_t>(s.declared_nu());
    for (ir::External& e : s.externals) {
        e.dargs_dq.assign(e.args.size(), Row(nq));
        e.dargs_dqd.assign(e.args.size(), Row(nq));
        e.dargs_du.assign(e.args.size(), Row(nu));
    }
    // Variables are numbered q, q', u, p (ir::Variables); the externals' own
    // channels never appear in their arguments.
    for (std::size_t k = 0; k < 2 * nq + nu; ++k) {
        ForwardDerivative d(s.graph, k);
        for (ir::External& e : s.externals)
            for (std::size_t i = 0; i < e.args.size(); ++i) {
                const NodeId v = d(e.args[i]);
                if (k < nq)
                    e.dargs_dq[i][k] = v;
                else if (k < 2 * nq)
                    e.dargs_dqd[i][k - nq] = v;
                else
                    e.dargs_du[i][k - 2 * nq] = v;
            }
    }
}

} // namespace yamsc::passes
