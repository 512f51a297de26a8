#include "codegen/linear_routines.hpp"

#include "codegen/routine_builder.hpp"
#include "codegen/symbol_binding.hpp"
#include "diag/diagnostics.hpp"

#include <utility>

namespace yamsc::codegen {
namespace {

using NodeMatrix = std::vector<std::vector<NodeId>>;

bool uses_accelerations(const Graph& g, const NodeMatrix& m) {
    const std::uint32_t bit = 1u << static_cast<int>(SymbolKind::acceleration);
    for (const auto& row : m)
        for (NodeId id : row)
            if (g.node(id).depends & bit) return true;
    return false;
}

/// M into the local `M` (lower triangle) and, when K0 needs them, the
/// accelerations qdd0 = M^-1 F; leaves M factorised.
void factor_and_solve_accelerations(RoutineBuilder& b, const LinearSources& in, int nq,
                                    bool accelerations) {
    b.local("M", nq * nq);
    if (accelerations) b.local("qdd0", nq);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j <= i; ++j) b.assign("M", i * nq + j, in.M[i][j]);
    if (accelerations)
        for (int i = 0; i < nq; ++i) b.assign("qdd0", i, in.F[static_cast<std::size_t>(i)]);
    b.factor("M", nq);
    if (accelerations) b.solve("M", nq, "qdd0", 0, 1);
}

Routine linear_routine(Graph& g, const LinearSources& in, int nq, int nu, bool accelerations,
                       const Options& options) {
    RoutineBuilder b(g, api_signature(RoutineId::linear), bind(SymbolSource::operating_point()));
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j <= i; ++j) b.assign("M0", i * nq + j, in.M[i][j]);
    for (int i = 0; i < nq; ++i)
        for (int j = i + 1; j < nq; ++j) b.copy("M0", i * nq + j, "M0", j * nq + i);
    if (accelerations) factor_and_solve_accelerations(b, in, nq, true);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nq; ++j)
            b.assign("C0", i * nq + j, g.add({{in.dF_dqd[i][j], -1.0}}, 0));
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nq; ++j)
            b.assign("K0", i * nq + j, g.add({{in.dMa_dq[i][j], 1.0}, {in.dF_dq[i][j], -1.0}}, 0));
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nu; ++j) b.assign("Q0", i * nu + j, in.dF_du[i][j]);
    return std::move(b).finish(options);
}

// A = [[0, I], [M^-1 (dF_dq - dMa_dq(a = q''0)), M^-1 dF_dqd]], B = [[0], [M^-1 dF_du]]:
// the lower block rows are solved in place, as in rhs_jacobian.
Routine state_space_routine(Graph& g, const LinearSources& in, int nq, int nu, bool accelerations,
                            const Options& options) {
    RoutineBuilder b(g, api_signature(RoutineId::state_space),
                     bind(SymbolSource::operating_point()));
    const int nx = 2 * nq;
    const NodeId zero = g.number(0.0), one = g.number(1.0);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nx; ++j) b.assign("A", i * nx + j, j == nq + i ? one : zero);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nu; ++j) b.assign("B", i * nu + j, zero);
    factor_and_solve_accelerations(b, in, nq, accelerations);
    for (int i = 0; i < nq; ++i) {
        for (int j = 0; j < nq; ++j)
            b.assign("A", (nq + i) * nx + j,
                     g.add({{in.dF_dq[i][j], 1.0}, {in.dMa_dq[i][j], -1.0}}, 0));
        for (int j = 0; j < nq; ++j) b.assign("A", (nq + i) * nx + nq + j, in.dF_dqd[i][j]);
    }
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nu; ++j) b.assign("B", (nq + i) * nu + j, in.dF_du[i][j]);
    b.solve("M", nq, "A", nq * nx, nx);
    if (nu > 0) b.solve("M", nq, "B", nq * nu, nu);
    return std::move(b).finish(options);
}

Routine output_matrices_routine(const Graph& g, const ir::System& s, const Options& options) {
    const int nu = s.nu(), nx = 2 * s.nq();
    RoutineBuilder b(g, api_signature(RoutineId::output_matrices),
                     bind(SymbolSource::operating_point()));
    for (std::size_t i = 0; i < s.C.size(); ++i)
        for (int j = 0; j < nx; ++j) b.assign("C", static_cast<int>(i) * nx + j, s.C[i][j]);
    for (std::size_t i = 0; i < s.D.size(); ++i)
        for (int j = 0; j < nu; ++j) b.assign("D", static_cast<int>(i) * nu + j, s.D[i][j]);
    return std::move(b).finish(options);
}

// Outputs that read q'' (reaction loads): y(q, q', u, q'') with q'' = M^-1 F, so
// C = ∂y/∂x + ∂y/∂q'' X_x and D = ∂y/∂u + ∂y/∂q'' X_u, where
// X = M0^-1 [dF_dq - dMa_dq, dF_dqd | dF_du] are the lower rows of [A | B]. X is
// solved in place in a local; its entries are read through the seed symbols
// (seed k = X[k], row-major nq x (2nq + nu)), which the unrolled form leaves free.
Routine output_matrices_with_accelerations(Graph& g, const ir::System& s, const LinearSources& in,
                                           const Options& options) {
    const int nq = s.nq(), nu = s.nu(), nx = 2 * nq, w = nx + nu;
    SymbolSource source = SymbolSource::operating_point();
    source.qdd = source.a; // y and its partials at q''0
    source.seed = "X";
    RoutineBuilder b(g, api_signature(RoutineId::output_matrices), bind(source));
    factor_and_solve_accelerations(b, in, nq, true);
    b.local("X", nq * w);
    for (int i = 0; i < nq; ++i) {
        for (int j = 0; j < nq; ++j)
            b.assign("X", i * w + j, g.add({{in.dF_dq[i][j], 1.0}, {in.dMa_dq[i][j], -1.0}}, 0));
        for (int j = 0; j < nq; ++j) b.assign("X", i * w + nq + j, in.dF_dqd[i][j]);
        for (int j = 0; j < nu; ++j) b.assign("X", i * w + nx + j, in.dF_du[i][j]);
    }
    b.solve("M", nq, "X", 0, w);
    auto chained = [&](std::size_t i, NodeId partial, int column) {
        const std::vector<NodeId>& dy = s.outputs[i].dqdd;
        std::vector<ir::Operand> terms{{partial, 1.0}};
        for (int r = 0; r < static_cast<int>(dy.size()); ++r) {
            const NodeId x = g.symbol({SymbolKind::seed, r * w + column});
            terms.push_back({g.mul({{dy[static_cast<std::size_t>(r)], 1.0}, {x, 1.0}}, 1.0), 1.0});
        }
        return g.add(std::move(terms), 0.0);
    };
    for (std::size_t i = 0; i < s.C.size(); ++i)
        for (int j = 0; j < nx; ++j)
            b.assign("C", static_cast<int>(i) * nx + j, chained(i, s.C[i][j], j));
    for (std::size_t i = 0; i < s.D.size(); ++i)
        for (int j = 0; j < nu; ++j)
            b.assign("D", static_cast<int>(i) * nu + j, chained(i, s.D[i][j], nx + j));
    return std::move(b).finish(options);
}

} // namespace

void add_linear_routines(Graph& graph, const ir::System& s, const LinearSources& in,
                         const Options& options, std::vector<Routine>& routines) {
    const int nq = s.nq(), nu = s.nu();
    if (nq == 0) return;
    const bool accelerations = uses_accelerations(graph, in.dMa_dq);
    routines.push_back(linear_routine(graph, in, nq, nu, accelerations, options));
    routines.push_back(state_space_routine(graph, in, nq, nu, accelerations, options));
    routines.push_back(s.outputs_read_accelerations()
                           ? output_matrices_with_accelerations(graph, s, in, options)
                           : output_matrices_routine(graph, s, options));
}

void add_operating_point(Module& module, const ir::System& s) {
    const ir::OperatingPoint& op = s.point;
    if (op.q.size() != s.dofs.size() || op.qd.size() != s.dofs.size() ||
        op.u.size() != static_cast<std::size_t>(s.declared_nu()))
        throw diag::InternalError("code generation: the operating point does not match the model");
    // Only parameters: the checker allows nothing else in the point.
    RoutineBuilder::Signature signature = api_signature(RoutineId::operating_point);
    signature.summary += op.declared ? " (its linearize block)" : " (no linearize block: zeros)";
    RoutineBuilder b(s.graph, std::move(signature), [](SymbolRef sym) -> std::optional<Expr> {
        if (sym.kind != SymbolKind::param) return std::nullopt;
        Expr e;
        e.kind = ExprKind::param;
        e.index = sym.index;
        return e;
    });
    for (std::size_t i = 0; i < op.q.size(); ++i) b.assign("q0", static_cast<int>(i), op.q[i]);
    for (std::size_t i = 0; i < op.qd.size(); ++i) b.assign("qd0", static_cast<int>(i), op.qd[i]);
    for (std::size_t i = 0; i < op.u.size(); ++i) b.assign("u0", static_cast<int>(i), op.u[i]);
    module.routines.push_back(std::move(b).finish(module.options));
}

} // namespace yamsc::codegen
