#include "codegen/constraint_routines.hpp"

#include "codegen/routine_builder.hpp"
#include "codegen/symbol_binding.hpp"

#include <algorithm>

namespace yamsc::codegen {

namespace {

void assign_matrix(RoutineBuilder& b, const char* array, const ir::Matrix& m) {
    for (std::size_t i = 0; i < m.size(); ++i)
        for (std::size_t j = 0; j < m[i].size(); ++j)
            b.assign(array, static_cast<int>(i * m[i].size() + j), m[i][j]);
}

/// The first `columns` columns of each row (the declared inputs of du blocks).
ir::Matrix first_columns(const ir::Matrix& m, int columns) {
    ir::Matrix out;
    for (const ir::Row& row : m) out.emplace_back(row.begin(), row.begin() + columns);
    return out;
}

/// Σ_k a[k] b[k].
NodeId dot(Graph& g, const std::vector<NodeId>& a, const std::vector<NodeId>& b) {
    std::vector<ir::Operand> terms;
    for (std::size_t k = 0; k < a.size(); ++k)
        terms.push_back({g.mul({{a[k], 1.0}, {b[k], 1.0}}, 1.0), 1.0});
    return g.add(std::move(terms), 0.0);
}

} // namespace

void add_constraint_routines(Graph& g, const ir::System& s, const Options& options,
                             std::vector<Routine>& routines) {
    const int nh = s.nh(), nu = s.declared_nu();
    {
        RoutineBuilder b(g, api_signature(RoutineId::constraints), bind({}));
        for (int i = 0; i < nh; ++i) b.assign("phi", i, s.constraints[i].phi);
        for (std::size_t i = 0; i < s.constraints.size(); ++i)
            b.assign("r", static_cast<int>(i), s.constraints[i].r);
        routines.push_back(std::move(b).finish(options));
    }
    {
        SymbolSource no_rates;
        no_rates.qd.clear(); // B reads no rates: r is linear in them
        RoutineBuilder b(g, api_signature(RoutineId::constraint_matrix), bind(no_rates));
        assign_matrix(b, "B", s.B);
        routines.push_back(std::move(b).finish(options));
    }
    {
        RoutineBuilder b(g, api_signature(RoutineId::constraint_bias), bind({}));
        for (std::size_t i = 0; i < s.gamma.size(); ++i)
            b.assign("gamma", static_cast<int>(i), s.gamma[i]);
        assign_matrix(b, "dr_dq", s.dr_dq);
        routines.push_back(std::move(b).finish(options));
    }
    {
        SymbolSource source;
        source.lambda = "lambda";
        source.a = "a";
        RoutineBuilder b(g, api_signature(RoutineId::constraint_jacobians), bind(source));
        assign_matrix(b, "dBTl_dq", s.dBTl_dq);
        assign_matrix(b, "dacc_dq", s.dacc_dq);
        assign_matrix(b, "dacc_dqd", s.dacc_dqd);
        assign_matrix(b, "dBTl_du", first_columns(s.dBTl_du, nu));
        assign_matrix(b, "dacc_du", first_columns(s.dacc_du, nu));
        routines.push_back(std::move(b).finish(options));
    }
}

Routine constrained_rhs_routine(Graph& g, const ir::System& s, const Options& options) {
    const int nq = s.nq(), nc = s.nc();
    // Y (nq x nc) is read back as the seed symbols, lambda as the multipliers and
    // the unconstrained q'' as `a`, each from the local that holds it.
    SymbolSource source = SymbolSource::state_vector(nq);
    source.a = "qdd";
    source.seed = "Y";
    source.lambda = "lambda";
    RoutineBuilder b(g, api_signature(RoutineId::rhs), bind(source));
    b.local("M", nq * nq);
    b.local("qdd", nq);
    b.local("Y", nq * nc);
    b.local("S", nc * nc);
    b.local("lambda", nc);
    for (int i = 0; i < nq; ++i) b.assign("xdot", i, g.symbol({SymbolKind::qd, i}));
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j <= i; ++j) b.assign("M", i * nq + j, s.M[i][j]);
    for (int i = 0; i < nq; ++i) b.assign("qdd", i, s.F[static_cast<std::size_t>(i)]);
    for (int i = 0; i < nq; ++i)
        for (int k = 0; k < nc; ++k) b.assign("Y", i * nc + k, s.B[k][i]);
    b.factor("M", nq);
    b.solve("M", nq, "qdd", 0, 1);
    b.solve("M", nq, "Y", 0, nc);
    std::vector<NodeId> unconstrained, multipliers;
    std::vector<std::vector<NodeId>> Y(static_cast<std::size_t>(nq));
    for (int i = 0; i < nq; ++i) {
        unconstrained.push_back(g.symbol({SymbolKind::acceleration, i}));
        for (int k = 0; k < nc; ++k) Y[i].push_back(g.symbol({SymbolKind::seed, i * nc + k}));
    }
    for (int k = 0; k < nc; ++k) multipliers.push_back(g.symbol({SymbolKind::multiplier, k}));
    for (int j = 0; j < nc; ++j) {
        for (int k = 0; k <= j; ++k) {
            std::vector<NodeId> column;
            for (int i = 0; i < nq; ++i) column.push_back(Y[i][k]);
            b.assign("S", j * nc + k, dot(g, s.B[j], column));
        }
        const NodeId residual =
            g.add({{dot(g, s.B[j], unconstrained), 1.0}, {s.gamma[j], 1.0}}, 0.0);
        b.assign("lambda", j, g.mul({{residual, 1.0}}, -1.0));
    }
    b.factor("S", nc);
    b.solve("S", nc, "lambda", 0, 1);
    for (int i = 0; i < nq; ++i)
        b.assign("xdot", nq + i,
                 g.add({{unconstrained[i], 1.0}, {dot(g, Y[i], multipliers), 1.0}}, 0.0));
    return std::move(b).finish(options);
}

} // namespace yamsc::codegen
