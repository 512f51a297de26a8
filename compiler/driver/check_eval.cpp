// `yamsc check` and `yamsc eval`: the front end only, no code generation.
#include "driver/bindings.hpp"
#include "driver/commands.hpp"
#include "driver/json.hpp"
#include "driver/pipeline.hpp"
#include "driver/sid_values.hpp"
#include "ir/evaluate.hpp"

#include <cmath>
#include <ostream>
#include <utility>
#include <vector>

namespace yamsc::driver {

namespace {

std::string frame_name(const model::Model& m, int i) {
    return i < 0 ? "ground" : m.bodies[static_cast<std::size_t>(i)].name;
}

/// What an external function loads and its C shape: `push(3 args -> genforce th)`.
std::string external_signature(const model::Model& m, const model::External& e) {
    std::string loads;
    if (e.kind == model::External::Kind::genforce) {
        loads = "genforce";
        for (int d : e.dofs) loads += " " + m.dofs[static_cast<std::size_t>(d)].name;
    } else {
        loads = std::string(e.kind == model::External::Kind::force ? "force" : "torque") + " on " +
                m.bodies[static_cast<std::size_t>(e.body)].name;
    }
    auto count = [](std::size_t n, const std::string& what) {
        return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
    };
    return e.name + "(" + count(e.args.size(), "arg") + " -> " +
           count(static_cast<std::size_t>(e.results()), "result") + ": " + loads + ")";
}

void check_text(const model::Model& m, std::ostream& out) {
    out << "model " << m.name;
    if (!m.title.empty()) out << " \"" << m.title << "\"";
    out << "\n";
    out << "dofs (" << m.dofs.size() << "):";
    for (const auto& d : m.dofs) out << " " << d.name;
    out << "\ninputs (" << m.inputs.size() << "):";
    for (const auto& i : m.inputs)
        out << " " << i.name << (i.order ? " order " + std::to_string(i.order) : "");
    out << "\nparameters (" << m.params.size() << "):";
    for (const auto& p : m.params) {
        out << " " << p.name;
        if (p.value) out << "=" << json::number(*p.value);
    }
    out << "\nbodies (" << m.bodies.size() << "):\n";
    for (const auto& b : m.bodies) {
        out << "  " << b.name << " (" << (b.kind == model::Body::Kind::rigid ? "rigid" : "flexible")
            << ") <- " << frame_name(m, b.parent) << ":";
        for (const auto& s : b.steps) {
            if (s.kind == model::Step::Kind::offset)
                out << " at";
            else if (s.kind == model::Step::Kind::node)
                out << " node "
                    << m.bodies[static_cast<std::size_t>(b.parent)]
                           .flex->sid->nodes[static_cast<std::size_t>(s.node)]
                           .id;
            else
                out << (s.kind == model::Step::Kind::rotate ? " rotate " : " translate ")
                    << ast::to_string(s.arg);
            out << ";";
        }
        if (b.flex) {
            out << " modes";
            for (std::size_t k = 0; k < b.flex->dofs.size(); ++k)
                out << " " << m.dofs[static_cast<std::size_t>(b.flex->dofs[k])].name;
            out << " (" << b.flex->description << ")";
        }
        out << "\n";
    }
    out << "outputs (" << m.outputs.size() << "):";
    for (const auto& o : m.outputs) out << " " << o.name;
    out << "\n";
    if (!m.constraints.empty()) {
        out << "constraints (" << m.constraints.size() << "):\n";
        for (const model::Constraint& c : m.constraints) {
            out << "  " << model::constraint_kind_info(c.kind).name << " " << c.name << ":";
            for (const model::ConstraintRow& r : c.rows)
                out << " " << r.name << (r.holonomic ? "" : " (velocity)");
            out << "\n";
        }
    }
    if (m.externals.empty()) return;
    out << "externals (" << m.externals.size() << "):\n";
    for (const auto& e : m.externals)
        out << "  " << external_signature(m, e) << (e.without_jacobian ? " without jacobian" : "")
            << "\n";
}

void check_json(const model::Model& m, std::ostream& out) {
    std::vector<std::string> dofs, inputs, params;
    for (const auto& d : m.dofs) dofs.push_back(d.name);
    for (const auto& i : m.inputs) inputs.push_back(i.name);
    out << "{\"model\":" << json::quote(m.name) << ",\"title\":" << json::quote(m.title)
        << ",\"dofs\":" << json::strings(dofs) << ",\"inputs\":" << json::strings(inputs)
        << ",\"parameters\":[";
    for (std::size_t i = 0; i < m.params.size(); ++i) {
        const auto& p = m.params[i];
        out << (i ? "," : "") << "{\"name\":" << json::quote(p.name)
            << ",\"default\":" << (p.value ? json::number(*p.value) : "null")
            << ",\"doc\":" << json::quote(p.doc) << "}";
    }
    out << "],\"bodies\":[";
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
        const auto& b = m.bodies[i];
        out << (i ? "," : "") << "{\"name\":" << json::quote(b.name) << ",\"kind\":"
            << json::quote(b.kind == model::Body::Kind::rigid ? "rigid" : "flexible")
            << ",\"parent\":" << json::quote(frame_name(m, b.parent)) << "}";
    }
    std::vector<std::string> outputs;
    for (const auto& o : m.outputs) outputs.push_back(o.name);
    out << "],\"outputs\":" << json::strings(outputs) << ",\"externals\":[";
    for (std::size_t i = 0; i < m.externals.size(); ++i) {
        const auto& e = m.externals[i];
        const char* kind = e.kind == model::External::Kind::force    ? "force"
                           : e.kind == model::External::Kind::torque ? "torque"
                                                                     : "genforce";
        std::vector<std::string> on;
        if (e.kind == model::External::Kind::genforce)
            for (int d : e.dofs) on.push_back(m.dofs[static_cast<std::size_t>(d)].name);
        else
            on.push_back(m.bodies[static_cast<std::size_t>(e.body)].name);
        out << (i ? "," : "") << "{\"name\":" << json::quote(e.name)
            << ",\"loads\":" << json::quote(kind) << ",\"on\":" << json::strings(on)
            << ",\"arguments\":" << e.args.size() << ",\"results\":" << e.results()
            << ",\"jacobian\":" << (e.without_jacobian ? "false" : "true") << "}";
    }
    out << "]}\n";
}

} // namespace

int check(const CheckOptions& o, std::ostream& out, std::ostream& err) {
    diag::Diagnostics diags;
    FrontEnd fe = run_front_end(o.model, Until::model, diags);
    err << diags.render();
    if (diags.has_errors() || !fe.model) return 1;
    if (o.json)
        check_json(*fe.model, out);
    else
        check_text(*fe.model, out);
    return 0;
}

namespace {

/// x = A^-1 b by Gaussian elimination with partial pivoting (M is small and SPD).
std::vector<double> solve(std::vector<std::vector<double>> A, std::vector<double> b) {
    const std::size_t n = b.size();
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t pivot = k;
        for (std::size_t r = k + 1; r < n; ++r)
            if (std::abs(A[r][k]) > std::abs(A[pivot][k])) pivot = r;
        std::swap(A[k], A[pivot]);
        std::swap(b[k], b[pivot]);
        for (std::size_t r = k + 1; r < n; ++r) {
            const double f = A[r][k] / A[k][k];
            for (std::size_t c = k; c < n; ++c) A[r][c] -= f * A[k][c];
            b[r] -= f * b[k];
        }
    }
    std::vector<double> x(n);
    for (std::size_t k = n; k-- > 0;) {
        double v = b[k];
        for (std::size_t c = k + 1; c < n; ++c) v -= A[k][c] * x[c];
        x[k] = v / A[k][k];
    }
    return x;
}

} // namespace

int eval(const EvalOptions& o, std::ostream& out, std::ostream& err) {
    diag::Diagnostics diags;
    FrontEnd fe = run_front_end(o.model, Until::system, diags);
    // The interpreter cannot call the user's functions: `--external` runs the
    // compiled code (eval_compiled), which the CLI chooses then.
    if (fe.model && !fe.model->externals.empty())
        for (const model::External& e : fe.model->externals)
            diags.error(diag::Kind::Io, e.loc,
                        "external function '" + e.name +
                            "' has no implementation: give --external lib.so or --external "
                            "file.c (eval then runs the compiled code)");
    err << diags.render();
    if (diags.has_errors() || !fe.system) return 1;
    const ir::System& sys = *fe.system;
    std::vector<Assignment> set =
        o.sid.empty() ? std::vector<Assignment>{} : sid_parameter_values(*fe.model, o.sid);
    set.insert(set.end(), o.set.begin(), o.set.end());
    const auto nq = static_cast<std::size_t>(sys.nq());

    std::vector<std::string> pnames, unames, dofs;
    std::vector<std::optional<double>> pdefaults;
    for (const auto& p : sys.params) {
        pnames.push_back(p.name);
        pdefaults.push_back(p.value);
    }
    for (const auto& u : sys.inputs) unames.push_back(u.name);
    for (const auto& d : sys.dofs) dofs.push_back(d.name);
    std::vector<double> p = bind_named(pnames, pdefaults, set, "parameter");
    std::vector<double> u =
        bind_named(unames, std::vector<std::optional<double>>(unames.size(), 0.0), o.u, "input");
    std::vector<double> q = o.q.empty() ? std::vector<double>(nq, 0.0) : sized(o.q, nq, "--q");
    std::vector<double> qd = o.qd.empty() ? std::vector<double>(nq, 0.0) : sized(o.qd, nq, "--qd");

    // M and F, then the outputs with q'' = M^-1 F (reaction loads read it); the M,
    // F of `approx` models approximated, as the generated code computes them.
    std::vector<double> qdd(nq, std::nan(""));
    auto value_of = [&](ir::SymbolRef s) -> double {
        const auto i = static_cast<std::size_t>(s.index);
        switch (s.kind) {
        case ir::SymbolKind::time:
            return o.t;
        case ir::SymbolKind::q:
            return q[i];
        case ir::SymbolKind::qd:
            return qd[i];
        case ir::SymbolKind::qdd:
            return qdd[i];
        case ir::SymbolKind::input:
            return u[i];
        case ir::SymbolKind::param:
            return p[i];
        default: // `a`: in the graph (M a), never read by M, F or y
            return std::nan("");
        }
    };
    std::vector<ir::NodeId> roots;
    for (const ir::Row& row : sys.M) roots.insert(roots.end(), row.begin(), row.end());
    roots.insert(roots.end(), sys.F.begin(), sys.F.end());
    const std::vector<double> values = ir::evaluate(sys.graph, roots, value_of);
    std::vector<std::vector<double>> M(nq, std::vector<double>(nq));
    std::vector<double> F(nq);
    std::size_t next = 0;
    for (std::size_t r = 0; r < nq; ++r)
        for (std::size_t c = 0; c < nq; ++c) M[r][c] = values[next++];
    for (std::size_t r = 0; r < nq; ++r) F[r] = values[next++];
    if (sys.outputs_read_accelerations()) qdd = solve(M, F);
    std::vector<ir::NodeId> output_roots;
    for (const ir::Output& output : sys.outputs) output_roots.push_back(output.value);
    const std::vector<double> y = ir::evaluate(sys.graph, output_roots, value_of);
    std::vector<std::string> onames;
    for (const auto& output : sys.outputs) onames.push_back(output.name);
    out << "{\"nq\":" << nq << ",\"dofs\":" << json::strings(dofs) << ",\"M\":" << json::matrix(M)
        << ",\"F\":" << json::array(F) << ",\"outputs\":" << json::strings(onames)
        << ",\"y\":" << json::array(y) << "}\n";
    return 0;
}

} // namespace yamsc::driver
