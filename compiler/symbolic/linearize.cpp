#include "symbolic/linearize.hpp"

#include "diag/diagnostics.hpp"
#include "symbolic/dag.hpp"
#include "symbolic/expressions.hpp"
#include "symbolic/tape.hpp"

#include <algorithm>

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

std::vector<ParameterDerivatives> parameter_derivatives(const Equations& eq,
                                                        const std::vector<std::size_t>& params) {
    const std::size_t nq = eq.dofs.size(), nu = eq.inputs.size();
    if (eq.dF_dq.size() != nq || eq.dF_dqd.size() != nq || eq.dF_du.size() != nq ||
        eq.dMa_dq.size() != nq || eq.M.size() != nq || eq.F.size() != nq)
        throw diag::InternalError("parameter derivatives need the Jacobians of the equations");
    // One variable per distinct parameter: a symbol listed twice would be the
    // variable of only one of its entries, and the other derivative would be 0.
    std::vector<symbol> variables;
    std::vector<std::size_t> variable_of(params.size());
    std::vector<std::size_t> distinct;
    for (std::size_t k = 0; k < params.size(); ++k) {
        if (params[k] >= eq.params.size()) throw diag::InternalError("no parameter of that index");
        const auto seen = std::find(distinct.begin(), distinct.end(), params[k]);
        variable_of[k] = static_cast<std::size_t>(seen - distinct.begin());
        if (seen == distinct.end()) {
            distinct.push_back(params[k]);
            variables.push_back(eq.params[params[k]].sym);
        }
    }
    Tape tape(variables);
    auto import_matrix = [&](const Matrix& m, std::size_t cols) {
        std::vector<std::vector<TapeId>> out(m.size());
        for (std::size_t r = 0; r < m.size(); ++r) {
            if (m[r].size() != cols) throw diag::InternalError("a Jacobian has the wrong shape");
            for (const ex& e : m[r]) out[r].push_back(tape.import(e));
        }
        return out;
    };
    // M: the lower triangle, all that M0 and its factorisation read.
    std::vector<std::vector<TapeId>> M(nq);
    for (std::size_t r = 0; r < nq; ++r)
        for (std::size_t c = 0; c <= r; ++c) M[r].push_back(tape.import(eq.M[r][c]));
    std::vector<TapeId> F;
    for (const ex& f : eq.F) F.push_back(tape.import(f));
    const auto dF_dq = import_matrix(eq.dF_dq, nq), dF_dqd = import_matrix(eq.dF_dqd, nq),
               dF_du = import_matrix(eq.dF_du, nu), dMa_dq = import_matrix(eq.dMa_dq, nq);

    std::vector<ParameterDerivatives> by_variable(variables.size());
    for (std::size_t k = 0; k < variables.size(); ++k) {
        ForwardDerivative d(tape, k);
        auto derive = [&](const std::vector<std::vector<TapeId>>& m, std::size_t cols) {
            Matrix dm(m.size(), Row(cols, 0));
            for (std::size_t r = 0; r < m.size(); ++r)
                for (std::size_t c = 0; c < m[r].size(); ++c) dm[r][c] = tape.to_ginac(d(m[r][c]));
            return dm;
        };
        ParameterDerivatives& pd = by_variable[k];
        pd.M = derive(M, nq);
        for (TapeId f : F) pd.F.push_back(tape.to_ginac(d(f)));
        pd.dF_dq = derive(dF_dq, nq);
        pd.dF_dqd = derive(dF_dqd, nq);
        pd.dF_du = derive(dF_du, nu);
        pd.dMa_dq = derive(dMa_dq, nq);
    }
    std::vector<ParameterDerivatives> out;
    for (std::size_t k = 0; k < params.size(); ++k) out.push_back(by_variable[variable_of[k]]);
    return out;
}

} // namespace yamsc::symbolic
