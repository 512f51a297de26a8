// build_module: lowers the System's rows to routines. Every routine reads the
// one graph of the System (a copy: lowering adds a few nodes such as K0's
// differences), so they all share the same value numbers.
#include "codegen/constraint_routines.hpp"
#include "codegen/linear_routines.hpp"
#include "codegen/module.hpp"
#include "codegen/output_routines.hpp"
#include "codegen/routine_builder.hpp"
#include "codegen/sensitivity_routines.hpp"
#include "codegen/sparse_ldlt.hpp"
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
    const NodeMatrix &M, &dF_dq, &dF_dqd, &dF_du, &dMa_dq;
    const NodeRow &F, y;
};

[[noreturn]] void malformed(const std::string& what) {
    throw diag::InternalError("code generation: malformed equations: " + what);
}

void check_shape(const NodeMatrix& m, int rows, int cols, const char* name) {
    bool ok = static_cast<int>(m.size()) == rows;
    for (const NodeRow& row : m) ok = ok && static_cast<int>(row.size()) == cols;
    if (!ok)
        malformed(std::string(name) + " is not " + std::to_string(rows) + " x " +
                  std::to_string(cols) + (m.empty() ? " (were the Jacobians derived?)" : ""));
}

void check_shapes(const ir::System& s, const Options& options) {
    const int nq = s.nq();
    check_shape(s.M, nq, nq, "M");
    if (static_cast<int>(s.F.size()) != nq) malformed("F does not have nq entries");
    check_shape(s.dF_dq, nq, nq, "dF_dq");
    check_shape(s.dF_dqd, nq, nq, "dF_dqd");
    check_shape(s.dF_du, nq, s.nu(), "dF_du");
    check_shape(s.dMa_dq, nq, nq, "dMa_dq");
    if (options.linear_model && nq > 0) {
        check_shape(s.C, s.ny(), 2 * nq, "C (the outputs' Jacobian)");
        check_shape(s.D, s.ny(), s.nu(), "D (the outputs' Jacobian)");
    }
    if (s.graph.max_multiplied_power() != options.max_multiplied_power)
        malformed("the IR's normal form has another max_multiplied_power");
}

ModelInfo model_info(const ir::System& s) {
    const int declared = s.declared_nu();
    ModelInfo m;
    m.name = s.model_name;
    m.title = s.title;
    m.source_path = s.source_path;
    m.source_digest = s.source_digest;
    for (const ir::Dof& d : s.dofs) m.dofs.push_back({d.name, d.doc});
    for (int i = 0; i < declared; ++i) m.inputs.push_back({s.inputs[i].name, s.inputs[i].doc});
    for (const ir::Parameter& p : s.params) m.params.push_back({p.name, p.doc, p.value});
    for (const ir::Output& y : s.outputs) m.outputs.push_back({y.name, y.doc});
    for (const ir::ConstraintRow& c : s.constraints)
        m.constraints.push_back({c.name, c.holonomic, c.dependent, c.source});
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
    RoutineBuilder b(g, api_signature(RoutineId::mass_matrix), bind(without_rates()));
    assign_lower_triangle(b, "M", in.M);
    // M is symmetric: the upper triangle repeats the lower one.
    for (int i = 0; i < nq; ++i)
        for (int j = i + 1; j < nq; ++j) b.copy("M", i * nq + j, "M", j * nq + i);
    return std::move(b).finish(options);
}

Routine forcing_routine(const Graph& g, const ImportedEquations& in, int nq,
                        const Options& options) {
    RoutineBuilder b(g, api_signature(RoutineId::forcing), bind({}));
    for (int i = 0; i < nq; ++i) b.assign("F", i, in.F[static_cast<std::size_t>(i)]);
    return std::move(b).finish(options);
}

Routine jacobians_routine(const Graph& g, const ImportedEquations& in, int nq, int nu,
                          const Options& options) {
    RoutineBuilder b(g, api_signature(RoutineId::jacobians), bind({}));
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nq; ++j) b.assign("dF_dq", i * nq + j, in.dF_dq[i][j]);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nq; ++j) b.assign("dF_dqd", i * nq + j, in.dF_dqd[i][j]);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nu; ++j) b.assign("dF_du", i * nu + j, in.dF_du[i][j]);
    return std::move(b).finish(options);
}

Routine rhs_routine(const Graph& g, const ImportedEquations& in, const std::vector<NodeId>& rates,
                    int nq, const Options& options) {
    RoutineBuilder b(g, api_signature(RoutineId::rhs), bind(SymbolSource::state_vector(nq)));
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
    RoutineBuilder b(g, api_signature(RoutineId::rhs_jacobian), bind(solved_accelerations(nq)));
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

// The externals' internal routines (codegen/external_wrappers.hpp calls them):
// their arguments, the arguments' derivatives, and M^-1 dF/dw for rhs_jacobian.
Argument arg(const char* name, ArgumentKind kind) {
    return argument(name, kind);
}

Routine internal(Routine r) {
    r.internal = true;
    return r;
}

void add_external_routines(Graph& g, const ir::System& s, const ImportedEquations& in,
                           const Options& options, Module& m) {
    const int nq = s.nq(), nu = s.declared_nu();
    const std::vector<Argument> q_form{
        arg("t", ArgumentKind::scalar), arg("q", ArgumentKind::input_array),
        arg("qd", ArgumentKind::input_array), arg("u", ArgumentKind::input_array),
        arg("p", ArgumentKind::params)};
    auto with = [&](std::vector<const char*> outs) {
        std::vector<Argument> a = q_form;
        for (const char* o : outs) a.push_back(arg(o, ArgumentKind::output_array));
        return a;
    };
    {
        RoutineBuilder b(g, "external_args", "the externals' arguments a(t, q, q', u)", with({"a"}),
                         bind({}));
        int k = 0;
        for (const ir::External& e : s.externals)
            for (NodeId a : e.args) b.assign("a", k++, a);
        m.routines.push_back(internal(std::move(b).finish(options)));
    }
    {
        RoutineBuilder b(g, "external_args_jacobian",
                         "da/dq, da/dq', da/du of the externals' arguments (na x nq, na x nq, "
                         "na x nu)",
                         with({"da_dq", "da_dqd", "da_du"}), bind({}));
        int k = 0;
        for (const ir::External& e : s.externals)
            for (std::size_t i = 0; i < e.args.size(); ++i, ++k) {
                for (int j = 0; j < nq; ++j) b.assign("da_dq", k * nq + j, e.dargs_dq[i][j]);
                for (int j = 0; j < nq; ++j) b.assign("da_dqd", k * nq + j, e.dargs_dqd[i][j]);
                for (int j = 0; j < nu; ++j) b.assign("da_du", k * nu + j, e.dargs_du[i][j]);
            }
        m.routines.push_back(internal(std::move(b).finish(options)));
    }
    {
        const int nw = s.nu() - nu;
        RoutineBuilder b(g, "external_qdd_dw",
                         "dq''/dw = M^-1 dF/dw for the externals' results w (nq x nw)",
                         {arg("t", ArgumentKind::scalar), arg("x", ArgumentKind::input_array),
                          arg("u", ArgumentKind::input_array), arg("p", ArgumentKind::params),
                          arg("B", ArgumentKind::output_array)},
                         bind(SymbolSource::state_vector(nq)));
        b.local("M", nq * nq);
        assign_lower_triangle(b, "M", in.M);
        b.factor("M", nq);
        for (int i = 0; i < nq; ++i)
            for (int k = 0; k < nw; ++k) b.assign("B", i * nw + k, in.dF_du[i][nu + k]);
        b.solve("M", nq, "B", 0, nw);
        m.routines.push_back(internal(std::move(b).finish(options)));
    }
    for (const ir::External& e : s.externals)
        m.externals.push_back({e.name, e.what, e.location, e.first_input, e.results,
                               static_cast<int>(e.args.size()), e.user_jacobian});
}

/// Every routine the module will have must find the passes it reads on the
/// System (routines.hpp): rows left empty by a pass that never ran would be
/// read as malformed equations, or worse, as zeros.
void check_passes(const ir::System& s, const Options& options) {
    RoutineSet built{RoutineId::mass_matrix, RoutineId::forcing, RoutineId::jacobians,
                     RoutineId::outputs,     RoutineId::rhs,     RoutineId::rhs_jacobian};
    if (options.linear_model && s.nq() > 0)
        built.insert({RoutineId::linear, RoutineId::state_space, RoutineId::output_matrices});
    if (!options.sensitivity_params.empty()) built.insert(RoutineId::linear_sensitivities);
    if (!s.constraints.empty()) {
        // The constrained motion's Jacobian and linear model are the runtime's
        // (in the independent coordinates); M^-1 F alone would be the tree's.
        built = built.without(RoutineSet{RoutineId::rhs_jacobian, RoutineId::linear,
                                         RoutineId::state_space, RoutineId::output_matrices,
                                         RoutineId::linear_sensitivities});
        built.insert(constraint_routines());
        if (s.tangent_form)
            throw diag::UserError("a model with constraints is compiled with unrolled "
                                  "Jacobians (--jacobians unrolled)");
        if (!options.sensitivity_params.empty())
            throw diag::UserError("--sensitivities of a model with constraints is not supported");
    }
    if (s.tangent_form) built = RoutineSet{};
    const ir::PassSet tangent{ir::Pass::derive_tangent};
    if (s.tangent_form && !s.passes.contains_all(tangent))
        malformed("the tangent form without passes::derive_tangent");
    built.for_each([&](RoutineId id) {
        if (!s.passes.contains_all(routine_row(id).needs))
            malformed(std::string(routine_name(id)) + " needs a pass that has not run");
    });
}

} // namespace

Module build_module(const ir::System& s, const Options& options) {
    check_passes(s, options);
    if (s.tangent_form) {
        Module m;
        m.model = model_info(s);
        m.options = options;
        add_tangent_routines(m, s);
        m.mass_ldlt = plan_ldlt(dense_pattern(s.nq())); // M by columns: no structure known
        return m;
    }
    check_shapes(s, options);
    const int nq = s.nq();
    Graph graph = s.graph;
    NodeRow y;
    for (const ir::Output& o : s.outputs) y.push_back(o.value);
    const ImportedEquations in{s.M, s.dF_dq, s.dF_dqd, s.dF_du, s.dMa_dq, s.F, y};
    std::vector<NodeId> rates;
    for (int i = 0; i < nq; ++i) rates.push_back(graph.symbol({SymbolKind::qd, i}));

    Module m;
    m.model = model_info(s);
    m.options = options;
    const std::uint32_t q_and_p =
        (1u << static_cast<int>(SymbolKind::q)) | (1u << static_cast<int>(SymbolKind::param));
    std::uint32_t mass_depends = 0;
    for (const NodeRow& row : in.M)
        for (NodeId id : row) mass_depends |= graph.node(id).depends;
    m.mass_matrix_short_form = (mass_depends & ~q_and_p) == 0;
    m.mass_ldlt = plan_ldlt(mass_pattern(graph, in.M));

    m.routines.push_back(mass_matrix_routine(graph, in, nq, options));
    m.routines.push_back(forcing_routine(graph, in, nq, options));
    m.routines.push_back(jacobians_routine(graph, in, nq, s.nu(), options));
    add_output_routines(graph, in.y, nq, s.outputs_read_accelerations(), options, m.routines);
    if (!s.constraints.empty()) {
        m.routines.push_back(constrained_rhs_routine(graph, s, options));
        add_constraint_routines(graph, s, options, m.routines);
        if (!s.externals.empty()) add_external_routines(graph, s, in, options, m);
        return m;
    }
    m.routines.push_back(rhs_routine(graph, in, rates, nq, options));
    m.routines.push_back(rhs_jacobian_routine(graph, in, nq, options));
    const LinearSources sources{in.M, in.F, in.dF_dq, in.dF_dqd, in.dF_du, in.dMa_dq};
    if (options.linear_model) add_linear_routines(graph, s, sources, options, m.routines);
    add_sensitivity_routine(graph, s, sources, options, m.routines); // only with sensitivity_params
    if (!s.externals.empty()) {
        if (!options.sensitivity_params.empty())
            throw diag::InternalError("code generation: sensitivities of a model with externals");
        add_external_routines(graph, s, in, options, m);
    }
    return m;
}

} // namespace yamsc::codegen
