// What the linear model needs beyond the Jacobians of F (paper section 2.5,
// docs/linearization.md): the Jacobians of the outputs, and for
// --sensitivities the derivatives of everything it is built from with respect
// to parameters. The matrices themselves (M0, C0, K0, Q0 at the operating
// point) are assembled by the code generator from these rows.
#include "diag/diagnostics.hpp"
#include "passes/forward.hpp"
#include "passes/pass_order.hpp"
#include "passes/passes.hpp"

#include <algorithm>

namespace yamsc::passes {

using ir::Matrix;
using ir::NodeId;
using ir::Row;

void output_jacobians(ir::System& s) {
    enter(s, ir::Pass::output_jacobians);
    ir::Graph& g = s.graph;
    const std::size_t nq = s.dofs.size(), nu = s.inputs.size(), ny = s.outputs.size();
    s.C.assign(ny, Row(2 * nq));
    s.D.assign(ny, Row(nu));
    for (std::size_t k = 0; k < 2 * nq + nu; ++k) {
        ForwardDerivative d(g, k);
        for (std::size_t i = 0; i < ny; ++i) {
            const NodeId dy = d(s.outputs[i].value);
            if (k < 2 * nq)
                s.C[i][k] = dy;
            else
                s.D[i][k - 2 * nq] = dy;
        }
    }
}

void parameter_derivatives(ir::System& s, const std::vector<std::size_t>& params) {
    enter(s, ir::Pass::parameter_derivatives);
    ir::Graph& g = s.graph;
    const std::size_t nq = s.dofs.size(), nu = s.inputs.size();
    if (s.dF_dq.size() != nq || s.dF_dqd.size() != nq || s.dF_du.size() != nq ||
        s.dMa_dq.size() != nq || s.M.size() != nq || s.F.size() != nq)
        throw diag::InternalError("parameter derivatives need the Jacobians of the equations");
    const std::size_t first_param = 2 * nq + nu; // Variables numbering
    std::vector<ir::ParameterDerivatives> out;
    for (std::size_t p : params) {
        if (p >= s.params.size()) throw diag::InternalError("no parameter of that index");
        ForwardDerivative d(g, first_param + p);
        auto derive = [&](const Matrix& m, std::size_t cols, bool lower) {
            Matrix dm(m.size());
            for (std::size_t r = 0; r < m.size(); ++r) {
                if (m[r].size() != cols)
                    throw diag::InternalError("a Jacobian has the wrong shape");
                for (std::size_t c = 0; c < (lower ? r + 1 : cols); ++c)
                    dm[r].push_back(d(m[r][c]));
            }
            return dm;
        };
        ir::ParameterDerivatives pd;
        pd.M = derive(s.M, nq, true); // the lower triangle: all M0 and its factorisation read
        for (NodeId f : s.F) pd.F.push_back(d(f));
        pd.dF_dq = derive(s.dF_dq, nq, false);
        pd.dF_dqd = derive(s.dF_dqd, nq, false);
        pd.dF_du = derive(s.dF_du, nu, false);
        pd.dMa_dq = derive(s.dMa_dq, nq, false);
        out.push_back(std::move(pd));
    }
    s.sensitivity_params = params;
    s.sensitivities = std::move(out);
}

} // namespace yamsc::passes
