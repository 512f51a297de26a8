#pragma once
// Test support: derive a model file's equations in-process, evaluate them with
// the exact DAG evaluator, and load its generated code compiled on the fly.
#include "analysis/jit.hpp"
#include "driver/pipeline.hpp"
#include "ir_to_ginac.hpp"
#include "lower/lower.hpp"
#include "passes/passes.hpp"
#include "symbolic/dag.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>

namespace yamsc::test {

inline std::string source_path(const std::string& relative) {
    return std::string(YAMSC_SOURCE_DIR) + "/" + relative;
}

/// The equations of a front end's run as compiled: for a model with `approx`, M
/// and F are the approximated ones (made on the IR by passes::approximate,
/// converted back to GiNaC here for comparisons with printed formulas).
inline symbolic::Equations compiled_equations(driver::FrontEnd& fe) {
    REQUIRE(fe.equations);
    REQUIRE(fe.system);
    symbolic::Equations eq = std::move(*fe.equations);
    if (!fe.system->exact_F.empty()) {
        IrToGinac to_ginac(fe.system->graph, eq);
        for (std::size_t r = 0; r < eq.M.size(); ++r)
            for (std::size_t c = 0; c < eq.M[r].size(); ++c)
                eq.M[r][c] = to_ginac(fe.system->M[r][c]);
        for (std::size_t r = 0; r < eq.F.size(); ++r) eq.F[r] = to_ginac(fe.system->F[r]);
    }
    return eq;
}

/// The equations of a model file as compiled (compiled_equations).
inline symbolic::Equations derive_file(const std::string& relative) {
    diag::Diagnostics diags;
    driver::FrontEnd fe =
        driver::run_front_end(source_path(relative), driver::Until::system, diags);
    INFO(diags.render());
    REQUIRE_FALSE(diags.has_errors());
    return compiled_equations(fe);
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
    driver::JitOptions o;
    o.cache_dir = std::string(YAMSC_TEST_BINARY_DIR) + "/jit-cache";
    Compiled c;
    ir::System s = lower::lower(eq);
    passes::derive_jacobians(s);
    passes::output_jacobians(s);
    c.library = driver::load_compiled_model(s, o);
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
