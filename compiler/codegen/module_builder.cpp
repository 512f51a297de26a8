// build_module: imports the equations into one canonical Graph (so that every
// routine shares the same value numbers) and lays out the routines.
#include "codegen/from_ginac.hpp"
#include "codegen/linear_routines.hpp"
#include "codegen/module.hpp"
#include "codegen/routine_builder.hpp"
#include "codegen/sensitivity_routines.hpp"
#include "codegen/symbol_binding.hpp"
#include "codegen/tangent_routines.hpp"
#include "diag/diagnostics.hpp"

#include <string>
#include <utility>
#include <vector>

namespace yamsc::codegen {
namespace {

using NodeRow = std::vector<NodeId>;
using NodeMatrix = std::vector<NodeRow>;

struct ImportedEquations {
    NodeMatrix M, dF_dq, dF_dqd, dF_du, dMa_dq;
    NodeRow F, y;
};

[[noreturn]] void malformed(const std::string& what) {
    throw diag::InternalError("code generation: malformed equations: " + what);
}

void check_shape(const symbolic::Matrix& m, int rows, int cols, const char* name) {
    bool ok = static_cast<int>(m.size()) == rows;
    for (const symbolic::Row& row : m) ok = ok && static_cast<int>(row.size()) == cols;
    if (!ok)
        malformed(std::string(name) + " is not " + std::to_string(rows) + " x " +
                  std::to_string(cols) + (m.empty() ? " (were the Jacobians derived?)" : ""));
}

void check_shapes(const symbolic::Equations& eq) {
    const int nq = eq.nq();
    check_shape(eq.M, nq, nq, "M");
    if (static_cast<int>(eq.F.size()) != nq) malformed("F does not have nq entries");
    check_shape(eq.dF_dq, nq, nq, "dF_dq");
    check_shape(eq.dF_dqd, nq, nq, "dF_dqd");
    check_shape(eq.dF_du, nq, eq.nu(), "dF_du");
    check_shape(eq.dMa_dq, nq, nq, "dMa_dq");
    if (static_cast<int>(eq.a.size()) != nq) malformed("the vector `a` does not have nq symbols");
}

NodeMatrix import_matrix(GinacImporter& importer, const symbolic::Matrix& m) {
    NodeMatrix out;
    for (const symbolic::Row& row : m) {
        NodeRow r;
        for (const GiNaC::ex& e : row) r.push_back(importer.import(e));
        out.push_back(std::move(r));
    }
    return out;
}

ModelInfo model_info(const symbolic::Equations& eq) {
    ModelInfo m;
    m.name = eq.model_name;
    m.title = eq.title;
    m.source_path = eq.source_path;
    m.source_digest = eq.source_digest;
    for (const symbolic::Dof& d : eq.dofs) m.dofs.push_back({d.name, d.doc});
    for (const symbolic::InputChannel& u : eq.inputs) m.inputs.push_back({u.name, u.doc});
    for (const symbolic::Parameter& p : eq.params) m.params.push_back({p.name, p.doc, p.value});
    for (const symbolic::Output& y : eq.outputs) m.outputs.push_back({y.name, y.doc});
    return m;
}

/// M reads no rates: a q' in it would be a malformed model.
SymbolSource without_rates() {
    SymbolSource s;
    s.qd.clear();
    return s;
}

/// rhs_jacobian: `a` bound to the accelerations solved into the local qdd.
SymbolSource solved_accelerations(int nq) {
    SymbolSource s = SymbolSource::state_vector(nq);
    s.a = "qdd";
    return s;
}

/// The lower triangle of M (all a factorisation reads), row by row.
void assign_lower_triangle(RoutineBuilder& b, const char* array, const NodeMatrix& M) {
    const int n = static_cast<int>(M.size());
    for (int i = 0; i < n; ++i)
        for (int j = 0; j <= i; ++j) b.assign(array, i * n + j, M[i][j]);
}

Routine mass_matrix_routine(const Graph& g, const ImportedEquations& in, int nq,
                            const Options& options) {
    RoutineBuilder b(g, api_signature("mass_matrix"), bind(without_rates()));
    assign_lower_triangle(b, "M", in.M);
    // M is symmetric: the upper triangle repeats the lower one.
    for (int i = 0; i < nq; ++i)
        for (int j = i + 1; j < nq; ++j) b.copy("M", i * nq + j, "M", j * nq + i);
    return std::move(b).finish(options);
}

Routine forcing_routine(const Graph& g, const ImportedEquations& in, int nq,
                        const Options& options) {
    RoutineBuilder b(g, api_signature("forcing"), bind({}));
    for (int i = 0; i < nq; ++i) b.assign("F", i, in.F[static_cast<std::size_t>(i)]);
    return std::move(b).finish(options);
}

Routine jacobians_routine(const Graph& g, const ImportedEquations& in, int nq, int nu,
                          const Options& options) {
    RoutineBuilder b(g, api_signature("jacobians"), bind({}));
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nq; ++j) b.assign("dF_dq", i * nq + j, in.dF_dq[i][j]);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nq; ++j) b.assign("dF_dqd", i * nq + j, in.dF_dqd[i][j]);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nu; ++j) b.assign("dF_du", i * nu + j, in.dF_du[i][j]);
    return std::move(b).finish(options);
}

Routine outputs_routine(const Graph& g, const ImportedEquations& in, const Options& options) {
    RoutineBuilder b(g, api_signature("outputs"), bind({}));
    for (std::size_t i = 0; i < in.y.size(); ++i) b.assign("y", static_cast<int>(i), in.y[i]);
    return std::move(b).finish(options);
}

Routine rhs_routine(const Graph& g, const ImportedEquations& in, const std::vector<NodeId>& rates,
                    int nq, const Options& options) {
    RoutineBuilder b(g, api_signature("rhs"), bind(SymbolSource::state_vector(nq)));
    if (nq > 0) b.local("M", nq * nq);
    for (int i = 0; i < nq; ++i) b.assign("xdot", i, rates[static_cast<std::size_t>(i)]);
    assign_lower_triangle(b, "M", in.M);
    for (int i = 0; i < nq; ++i) b.assign("xdot", nq + i, in.F[static_cast<std::size_t>(i)]);
    if (nq > 0) {
        b.factor("M", nq);
        b.solve("M", nq, "xdot", nq, 1);
    }
    return std::move(b).finish(options);
}

// J = [[0, I], [M^-1 (dF_dq - dMa_dq(a = q'')), M^-1 dF_dqd]]: the lower block
// rows of J are an nq x 2nq row-major matrix, solved in place.
Routine rhs_jacobian_routine(Graph& g, const ImportedEquations& in, int nq,
                             const Options& options) {
    RoutineBuilder b(g, api_signature("rhs_jacobian"), bind(solved_accelerations(nq)));
    const int nx = 2 * nq;
    const NodeId zero = g.number(0.0);
    const NodeId one = g.number(1.0);
    std::vector<std::vector<NodeId>> lower_rows(static_cast<std::size_t>(nq));
    for (int i = 0; i < nq; ++i) {
        for (int j = 0; j < nq; ++j)
            lower_rows[i].push_back(g.add({{in.dF_dq[i][j], 1.0}, {in.dMa_dq[i][j], -1.0}}, 0.0));
        for (int j = 0; j < nq; ++j) lower_rows[i].push_back(in.dF_dqd[i][j]);
    }
    if (nq > 0) {
        b.local("M", nq * nq);
        b.local("qdd", nq);
    }
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nx; ++j) b.assign("J", i * nx + j, j == nq + i ? one : zero);
    assign_lower_triangle(b, "M", in.M);
    for (int i = 0; i < nq; ++i) b.assign("qdd", i, in.F[static_cast<std::size_t>(i)]);
    if (nq == 0) return std::move(b).finish(options);
    b.factor("M", nq);
    b.solve("M", nq, "qdd", 0, 1);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nx; ++j) b.assign("J", (nq + i) * nx + j, lower_rows[i][j]);
    b.solve("M", nq, "J", nq * nx, nx);
    return std::move(b).finish(options);
}

} // namespace

Module build_module(const symbolic::Equations& eq, const Options& options) {
    if (eq.tangent_form) {
        Module m;
        m.model = model_info(eq);
        m.options = options;
        add_tangent_routines(m, eq);
        return m;
    }
    check_shapes(eq);
    const int nq = eq.nq();
    Graph graph(options.max_multiplied_power);
    GinacImporter importer(graph, eq);
    ImportedEquations in;
    in.M = import_matrix(importer, eq.M);
    for (const GiNaC::ex& f : eq.F) in.F.push_back(importer.import(f));
    in.dF_dq = import_matrix(importer, eq.dF_dq);
    in.dF_dqd = import_matrix(importer, eq.dF_dqd);
    in.dF_du = import_matrix(importer, eq.dF_du);
    in.dMa_dq = import_matrix(importer, eq.dMa_dq);
    for (const symbolic::Output& y : eq.outputs) in.y.push_back(importer.import(y.value));
    std::vector<NodeId> rates;
    for (int i = 0; i < nq; ++i) rates.push_back(graph.symbol({SymbolKind::qd, i}));

    Module m;
    m.model = model_info(eq);
    m.options = options;
    const std::uint32_t q_and_p =
        (1u << static_cast<int>(SymbolKind::q)) | (1u << static_cast<int>(SymbolKind::param));
    std::uint32_t mass_depends = 0;
    for (const NodeRow& row : in.M)
        for (NodeId id : row) mass_depends |= graph.node(id).depends;
    m.mass_matrix_short_form = (mass_depends & ~q_and_p) == 0;

    m.routines.push_back(mass_matrix_routine(graph, in, nq, options));
    m.routines.push_back(forcing_routine(graph, in, nq, options));
    m.routines.push_back(jacobians_routine(graph, in, nq, eq.nu(), options));
    m.routines.push_back(outputs_routine(graph, in, options));
    m.routines.push_back(rhs_routine(graph, in, rates, nq, options));
    m.routines.push_back(rhs_jacobian_routine(graph, in, nq, options));
    if (options.linear_model)
        add_linear_routines(graph, importer, eq,
                            {in.M, in.F, in.dF_dq, in.dF_dqd, in.dF_du, in.dMa_dq}, options,
                            m.routines);
    add_sensitivity_routine(graph, importer, eq,
                            {in.M, in.F, in.dF_dq, in.dF_dqd, in.dF_du, in.dMa_dq}, options,
                            m.routines); // only with options.sensitivity_params
    return m;
}

} // namespace yamsc::codegen
