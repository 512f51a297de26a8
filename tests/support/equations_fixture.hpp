#pragma once
// Test support: derive a model file's equations in-process, evaluate them with
// the exact DAG evaluator, and load its generated code compiled on the fly.
#include "analysis/jit.hpp"
#include "driver/pipeline.hpp"
#include "ir_to_ginac.hpp"
#include "lower/lower.hpp"
#include "passes/passes.hpp"
#include "symbolic/dag.hpp"
#include "symbolic/derive.hpp"
#include "symbolic/linearize.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>

namespace yamsc::test {

inline std::string source_path(const std::string& relative) {
    return std::string(YAMSC_SOURCE_DIR) + "/" + relative;
}

/// A model file's front end with its GiNaC equations: derived in this process,
/// as the derivation module does it (derivation/module/entry.cpp), since the
/// module keeps the equations to itself and hands over the ir::System only.
struct InProcess {
    driver::FrontEnd fe;
    std::optional<symbolic::Equations> equations;
};

inline InProcess derive_in_process(const std::string& path, driver::Until until,
                                   diag::Diagnostics& diags) {
    InProcess out;
    out.fe = driver::run_front_end(path, driver::Until::model, diags);
    if (!out.fe.model || diags.has_errors()) return out;
    const bool tangent =
        driver::uses_tangent_form(*out.fe.model, until, driver::Derivatives::automatic);
    const model::Model derived = model::with_external_channels(*out.fe.model);
    symbolic::DeriveOptions options; // as the derivation module derives
    options.mass_matrix = !tangent;
    options.cost = lower::operation_count;
    out.equations = symbolic::derive(derived, diags, options);
    if (!out.equations || diags.has_errors()) return out;
    out.equations->source_path = path;
    out.fe.system =
        lower::lower(*out.equations, symbolic::operating_point(derived, *out.equations));
    driver::finish_front_end(out.fe, until, tangent, diags);
    return out;
}

/// The equations of an in-process run as compiled: for a model with `approx`, M
/// and F are the approximated ones (made on the IR by passes::approximate,
/// converted back to GiNaC here for comparisons with printed formulas).
inline symbolic::Equations compiled_equations(InProcess& run) {
    REQUIRE(run.equations);
    REQUIRE(run.fe.system);
    symbolic::Equations eq = std::move(*run.equations);
    const ir::System& system = *run.fe.system;
    if (!system.exact_F.empty()) {
        IrToGinac to_ginac(system.graph, eq);
        for (std::size_t r = 0; r < eq.M.size(); ++r)
            for (std::size_t c = 0; c < eq.M[r].size(); ++c) eq.M[r][c] = to_ginac(system.M[r][c]);
        for (std::size_t r = 0; r < eq.F.size(); ++r) eq.F[r] = to_ginac(system.F[r]);
    }
    return eq;
}

/// The equations of a model file as compiled (compiled_equations).
inline symbolic::Equations derive_file(const std::string& relative) {
    diag::Diagnostics diags;
    InProcess run = derive_in_process(source_path(relative), driver::Until::system, diags);
    INFO(diags.render());
    REQUIRE_FALSE(diags.has_errors());
    return compiled_equations(run);
}

/// M and F of the symbolic equations at a state, parameters at their defaults
/// unless overridden by name.
struct Evaluated {
    std::vector<std::vector<double>> M;
    std::vector<double> F;
};

inline Evaluated evaluate(const symbolic::Equations& eq, const std::vector<double>& q,
                          const std::vector<double>& qd, const std::vector<double>& u = {},
                          const std::map<std::string, double>& params = {}, double t = 0) {
    symbolic::Evaluator::Values v;
    v[eq.t] = t;
    for (std::size_t i = 0; i < eq.dofs.size(); ++i) {
        v[eq.dofs[i].q] = q.at(i);
        v[eq.dofs[i].qd] = qd.at(i);
    }
    for (std::size_t i = 0; i < eq.inputs.size(); ++i)
        v[eq.inputs[i].sym] = u.empty() ? 0.0 : u.at(i);
    for (const auto& p : eq.params) {
        auto it = params.find(p.name);
        v[p.sym] = it != params.end() ? it->second : p.value.value_or(NAN);
    }
    symbolic::Evaluator e(v);
    Evaluated out;
    const std::size_t n = eq.dofs.size();
    out.M.assign(n, std::vector<double>(n));
    for (std::size_t r = 0; r < n; ++r) {
        for (std::size_t s = 0; s < n; ++s) out.M[r][s] = e(eq.M[r][s]);
        out.F.push_back(e(eq.F[r]));
    }
    return out;
}

/// The generated code of a model, compiled into a shared library (cached in the
/// test build folder) and bound to its default parameters (overridable).
struct Compiled {
    std::unique_ptr<runtime::SharedModel> library;
    runtime::ModelView view;
};

inline Compiled compile_model(const symbolic::Equations& eq,
                              const std::map<std::string, double>& params = {}) {
    analysis::JitOptions o;
    o.cache_dir = std::string(YAMSC_TEST_BINARY_DIR) + "/jit-cache";
    Compiled c;
    ir::System s = lower::lower(eq);
    passes::derive_jacobians(s);
    passes::output_jacobians(s);
    if (!s.constraints.empty()) passes::constraint_derivatives(s); // as the pass pipeline
    c.library = analysis::load_compiled_model(s, o);
    std::vector<double> p = c.library->default_params();
    for (const auto& [name, value] : params) {
        int i = c.library->param_index(name);
        REQUIRE(i >= 0);
        p[static_cast<std::size_t>(i)] = value;
    }
    c.view = c.library->view(p);
    return c;
}

/// Kinetic energy q'ᵀ M(q) q' / 2 of a scleronomic model at x = [q, q'].
inline double kinetic_energy(const runtime::ModelView& v, double t, const double* x) {
    const int nq = v.nq;
    std::vector<double> M(static_cast<std::size_t>(nq * nq));
    v.mass_matrix(t, x, nullptr, M.data());
    double T = 0;
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nq; ++j)
            T += 0.5 * x[nq + i] * M[static_cast<std::size_t>(i * nq + j)] * x[nq + j];
    return T;
}

inline double max_abs(const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::fabs(x));
    return m;
}

} // namespace yamsc::test
