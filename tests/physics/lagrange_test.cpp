// Lagrange consistency: the equations M(q) q'' = F(q, q', u, t) that Kane's
// method gives must be Lagrange's equations of the kinetic energy the same
// kinematics give, T = ½ q'ᵀ M q' (+ terms linear in q' and of order 0 under
// prescribed motion). The part of F quadratic in q' is then fixed by M alone,
// minus d/dt(M) q' plus ∂T/∂q:
//
//     F₂,i(q, q') = -Σ_jk (∂M_ij/∂q_k - ½ ∂M_jk/∂q_i) q'_j q'_k.
//
// F₂ is the even part of F in q' less F(q, 0): ½ (F(q, q') + F(q, -q')) -
// F(q, 0). Gravity, elastic and applied loads (order 0 in q'), damping and the
// gyroscopic and transport terms of prescribed motion (linear in q') drop out,
// so the check holds for rheonomic models too (∂M/∂t q' is linear in q'); that
// F₂ has no other part is checked with F₂(q, 2q') = 4 F₂(q, q'). ∂M/∂q comes
// from central differences of M.
//
// Checked: every model of models/ as shipped, through its generated code, and
// every model with a joint on a node under each `elastic_rotation` option,
// through the exact evaluation of its equations (the generated code equals it
// to 1e-12, properties_test.cpp). Two modelling choices are Lagrangian only to
// the order they keep, by design; the models that use them are checked without
// them, and the residual they leave is reported:
// - `approx` in a DOF: truncation does not commute with ∂/∂q (the Christoffel
//   terms of the truncated M are not the truncated ones of M);
// - the shape integrals of a flexible body whose frame turns with the DOFs:
//   the SID keeps the body's inertia to first order in its elastic coordinates
//   (J(q) = J⁰ + J¹ q) while the loads of the turning frame use Oe(q), Gr, Ge,
//   whose first-order parts stand for second-order inertia and carry the
//   geometric stiffness (docs/theory.md). Such a body is made massless when its
//   shape integrals are parameters (`symbolic modes`); otherwise the model is
//   checked at zero deflection of that body, and its elastic rotation options
//   against the `exact` one (the body's own residual is the same for all).
#include "equations_fixture.hpp"
#include "symbolic/kinematics.hpp"
#include "test_files.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <regex>
#include <sstream>

using namespace yamsc;

namespace {

using Vector = std::vector<double>;
using Params = std::map<std::string, double>;

/// M(q, u) (row-major) and F(q, q', u) of a model at a fixed time.
struct Functions {
    int nq = 0, nu = 0;
    std::function<Vector(const Vector& q, const Vector& u)> M;
    std::function<Vector(const Vector& q, const Vector& qd, const Vector& u)> F;
};

constexpr double t_check = 0.3;

// The largest residual accepted, relative to the terms compared. The
// differences resolve them to ~1e-10; the kinematic inconsistencies this test
// is for are of the order of the terms themselves.
constexpr double tolerance = 1e-6;

Functions compiled(const runtime::ModelView& v) {
    Functions f;
    f.nq = v.nq;
    f.nu = v.nu;
    const auto n = static_cast<std::size_t>(v.nq);
    f.M = [&v, n](const Vector& q, const Vector& u) {
        Vector M(n * n);
        v.mass_matrix(t_check, q.data(), u.data(), M.data());
        return M;
    };
    f.F = [&v, n](const Vector& q, const Vector& qd, const Vector& u) {
        Vector F(n);
        v.forcing(t_check, q.data(), qd.data(), u.data(), F.data());
        return F;
    };
    return f;
}

/// The exact evaluation of the equations, parameters at their defaults unless
/// given.
Functions exact(const symbolic::Equations& eq, const Params& params = {}) {
    Functions f;
    f.nq = eq.nq();
    f.nu = eq.nu();
    f.M = [&eq, params](const Vector& q, const Vector& u) {
        const auto e = test::evaluate(eq, q, Vector(q.size(), 0.0), u, params, t_check);
        Vector M;
        for (const auto& row : e.M) M.insert(M.end(), row.begin(), row.end());
        return M;
    };
    f.F = [&eq, params](const Vector& q, const Vector& qd, const Vector& u) {
        return test::evaluate(eq, q, qd, u, params, t_check).F;
    };
    return f;
}

/// The residual F₂ + Christoffel terms of each row at one state, its scale (the
/// sum of the magnitudes of the terms compared) and F₂(2q') - 4 F₂(q').
struct Rows {
    Vector residual, scale, not_quadratic;
};

Rows residual_rows(const Functions& f, const Vector& q, const Vector& qd, const Vector& u) {
    const auto n = static_cast<std::size_t>(f.nq);
    const auto F0 = f.F(q, Vector(n, 0.0), u);
    auto even = [&](double s) {
        Vector plus = qd, minus = qd;
        for (std::size_t i = 0; i < n; ++i) {
            plus[i] *= s;
            minus[i] *= -s;
        }
        const auto Fp = f.F(q, plus, u), Fm = f.F(q, minus, u);
        Vector e(n);
        for (std::size_t i = 0; i < n; ++i) e[i] = 0.5 * (Fp[i] + Fm[i]) - F0[i];
        return e;
    };
    const auto F2 = even(1), F2_twice = even(2);

    // dM[k] = ∂M/∂q_k by fourth-order central differences: the truncation
    // error (h⁴) is negligible, the round-off about eps |M| / h.
    constexpr double h = 1e-3;
    std::vector<Vector> dM(n);
    double mmax = 0;
    for (double x : f.M(q, u)) mmax = std::max(mmax, std::fabs(x));
    for (std::size_t k = 0; k < n; ++k) {
        auto at = [&](double step) {
            auto qs = q;
            qs[k] += step;
            return f.M(qs, u);
        };
        const auto M2p = at(2 * h), Mp = at(h), Mm = at(-h), M2m = at(-2 * h);
        dM[k].resize(n * n);
        for (std::size_t i = 0; i < n * n; ++i)
            dM[k][i] = (8 * (Mp[i] - Mm[i]) - (M2p[i] - M2m[i])) / (12 * h);
    }
    double qd2 = 0;
    for (double x : qd) qd2 += x * x;
    // What round-off leaves of a row (M evaluated to ~100 eps, divided by h):
    // residuals below it mean nothing, so a row's scale is at least
    // round-off / tolerance.
    const double floor = 1e2 * 2.2e-16 * mmax * qd2 / h / tolerance;

    Rows r;
    for (std::size_t i = 0; i < n; ++i) {
        double christoffel = 0, scale = std::fabs(F2[i]);
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t k = 0; k < n; ++k) {
                const double a = dM[k][i * n + j] * qd[j] * qd[k];
                const double b = 0.5 * dM[i][j * n + k] * qd[j] * qd[k];
                christoffel += a - b;
                scale += std::fabs(a) + std::fabs(b);
            }
        r.residual.push_back(F2[i] + christoffel);
        r.scale.push_back(std::max(scale, floor));
        r.not_quadratic.push_back(F2_twice[i] - 4 * F2[i]);
    }
    return r;
}

struct State {
    Vector q, qd, u;
};

/// Random states: q and q' in [-1, 1], inputs in [-1000, 1000]; the DOFs in
/// `held` at 0.
std::vector<State> random_states(const Functions& f, unsigned seed,
                                 const std::vector<int>& held = {}) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(-1, 1);
    std::vector<State> out(4);
    for (State& s : out) {
        for (int i = 0; i < f.nq; ++i) {
            const bool zero = std::find(held.begin(), held.end(), i) != held.end();
            s.q.push_back(zero ? 0.0 : U(rng));
            s.qd.push_back(U(rng));
        }
        for (int i = 0; i < f.nu; ++i) s.u.push_back(1000 * U(rng));
    }
    return out;
}

struct Worst {
    double lagrange = 0;  // max over rows and states of |residual| / scale
    double quadratic = 0; // the same for F₂(2q') - 4 F₂(q')
};

/// The worst residuals over the states; with `reference`, of the residual less
/// the reference's at the same states.
Worst worst(const Functions& f, const std::vector<State>& states,
            const std::vector<Rows>* reference = nullptr, std::vector<Rows>* rows_out = nullptr) {
    Worst w;
    for (std::size_t k = 0; k < states.size(); ++k) {
        const Rows r = residual_rows(f, states[k].q, states[k].qd, states[k].u);
        for (std::size_t i = 0; i < r.residual.size(); ++i) {
            const double res = r.residual[i] - (reference ? (*reference)[k].residual[i] : 0.0);
            w.lagrange = std::max(w.lagrange, std::fabs(res) / r.scale[i]);
            w.quadratic = std::max(w.quadratic, std::fabs(r.not_quadratic[i]) / r.scale[i]);
        }
        if (rows_out) rows_out->push_back(r);
    }
    return w;
}

std::vector<std::string> shipped_models() {
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(test::source_path("models")))
        if (entry.path().extension() == ".mbd")
            out.push_back("models/" + entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

std::string stem(const std::string& path) {
    return std::filesystem::path(path).stem().string();
}

/// The model's lines without its `approx` statements.
std::string without_approx(const std::string& text) {
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line))
        if (line.rfind("approx", 0) != 0) out += line + "\n";
    return out;
}

/// Whether an `approx` statement of the model names one of its DOFs.
bool approximates_a_dof(const std::string& text, const symbolic::Equations& eq) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("approx", 0) != 0) continue;
        for (const auto& d : eq.dofs)
            if (std::regex_search(line, std::regex("[\\s,]" + d.name + "[\\s,]"))) return true;
    }
    return false;
}

/// The flexible bodies of a model whose frames turn with its DOFs (their
/// angular velocity depends on q'): for each, its name and its modes' DOFs.
std::vector<std::pair<std::string, std::vector<int>>>
turning_flexible_bodies(const std::string& path) {
    diag::Diagnostics diags;
    auto fe = driver::run_front_end(path, driver::Until::model, diags);
    REQUIRE(fe.model);
    symbolic::Symbols symbols(*fe.model);
    const auto frames = symbolic::body_frames(*fe.model, symbols);
    std::vector<std::pair<std::string, std::vector<int>>> out;
    for (std::size_t b = 0; b < frames.size(); ++b) {
        const auto& body = fe.model->bodies[b];
        if (body.flex && !frames[b].Jw.empty()) out.emplace_back(body.name, body.flex->dofs);
    }
    return out;
}

/// Parameter values that remove the inertia of the given flexible bodies (their
/// mass and shape integrals, not their nodes, stiffness or damping), when they
/// are `symbolic modes`; empty otherwise.
Params massless(const symbolic::Equations& eq,
                const std::vector<std::pair<std::string, std::vector<int>>>& bodies) {
    Params out;
    for (const auto& [name, dofs] : bodies) {
        const std::regex inertial(name + "_(mass|(mdCM|J|Ct|Cr|Me|Oe|Gr|Ge)1?_.*)");
        for (const auto& p : eq.params)
            if (std::regex_match(p.name, inertial)) out[p.name] = 0;
    }
    return out;
}

/// Every joint on a node of the model given `elastic_rotation = word`; empty
/// when the model has none.
std::string with_rotation(const std::string& text, const std::string& word) {
    static const std::regex joint(
        R"((joint\s+\w+\.(?:tip|node\s*\([^)]*\))\s*->\s*\w+)[ \t]*(?:\{([^}]*)\})?)");
    static const std::regex option(R"(elastic_rotation\s*=\s*\w+\s*;?\s*)");
    std::string out;
    auto last = text.cbegin();
    bool found = false;
    for (std::sregex_iterator it(text.begin(), text.end(), joint), end; it != end; ++it) {
        const std::smatch& m = *it;
        out.append(last, m[0].first);
        std::string rest = std::regex_replace(m[2].str(), option, "");
        rest.erase(0, rest.find_first_not_of(" \t\n"));
        rest.erase(rest.find_last_not_of(" \t\n") + 1);
        out +=
            m[1].str() + " { elastic_rotation = " + word + (rest.empty() ? "" : "; " + rest) + " }";
        last = m[0].second;
        found = true;
    }
    if (!found) return {};
    out.append(last, text.cend());
    return out;
}

/// Derives a model given as text (its data files are those of models/data).
symbolic::Equations derive_text(const std::string& text, const std::string& name,
                                driver::Until until = driver::Until::system) {
    const std::string path = test_support::scratch_dir("lagrange", name) + "/" + name + ".mbd";
    test_support::write_file(
        path, test_support::replace_all(text, "\"data/", "\"" + test::source_path("models/data/")));
    diag::Diagnostics diags;
    test::InProcess run = test::derive_in_process(path, until, diags);
    INFO(diags.render());
    REQUIRE_FALSE(diags.has_errors());
    REQUIRE(run.equations);
    return std::move(*run.equations);
}

} // namespace

TEST_CASE("shipped models: F's velocity terms are the Christoffel terms of M (generated code)") {
    int checked_whole = 0;
    for (const std::string& path : shipped_models()) {
        CAPTURE(path);
        std::string text = test_support::read_file(test::source_path(path));
        auto eq = test::derive_file(path);
        const bool by_approx = approximates_a_dof(text, eq);
        const auto turning = turning_flexible_bodies(test::source_path(path));
        Params params;
        std::vector<int> held; // DOFs at 0 in the states checked
        if (by_approx || !turning.empty()) {
            MESSAGE(path << ": residual " << worst(exact(eq), random_states(exact(eq), 5)).lagrange
                         << " as shipped, from "
                         << std::string(by_approx ? "approx in a DOF and " : "")
                         << "the first-order inertia of a turning flexible body");
            if (by_approx)
                eq = derive_text(without_approx(text), stem(path) + "_without_approx",
                                 driver::Until::jacobians);
            params = massless(eq, turning);
            if (params.empty())
                for (const auto& body : turning)
                    held.insert(held.end(), body.second.begin(), body.second.end());
        } else {
            ++checked_whole;
        }
        auto c = test::compile_model(eq, params);
        const auto f = compiled(c.view);
        const Worst w = worst(f, random_states(f, 7, held));
        MESSAGE(path << ": Lagrange residual " << w.lagrange << ", not quadratic " << w.quadratic
                     << std::string(params.empty() ? "" : " (flexible body massless)")
                     << std::string(held.empty() ? "" : " (flexible body at zero deflection)"));
        CHECK(w.quadratic < tolerance);
        CHECK(w.lagrange < tolerance);
    }
    // Only the floating turbines with a flexible tower need a variant: the
    // template, the paper's 3-DOF one and the same with its loads as blocks.
    CHECK(checked_whole == static_cast<int>(shipped_models().size()) - 3);
}

TEST_CASE("every elastic_rotation option: F's velocity terms are the Christoffel terms of M") {
    const std::vector<std::string> words = {"exact",     "small",     "exact_xyz", "exact_xzy",
                                            "exact_yxz", "exact_yzx", "exact_zxy", "exact_zyx"};
    std::vector<std::string> models = shipped_models();
    models.push_back("tests/physics/models/tower_top_mass.mbd");
    int variants = 0;
    for (const std::string& path : models) {
        const std::string text = without_approx(test_support::read_file(test::source_path(path)));
        const auto turning = turning_flexible_bodies(test::source_path(path));
        // With a turning flexible body that cannot be made massless, every
        // option is compared with `exact` (the first word).
        std::vector<Rows> reference;
        for (const std::string& word : words) {
            const std::string variant = with_rotation(text, word);
            if (variant.empty()) break; // no joint on a node
            CAPTURE(path);
            CAPTURE(word);
            const auto eq = derive_text(variant, stem(path) + "_" + word);
            const Params params = massless(eq, turning);
            const auto f = exact(eq, params);
            const bool relative = !turning.empty() && params.empty();
            const bool first = reference.empty();
            const Worst w =
                worst(f, random_states(f, 13), relative && !first ? &reference : nullptr,
                      relative && first ? &reference : nullptr);
            MESSAGE(path << " with elastic_rotation = " << word << ": Lagrange residual "
                         << w.lagrange
                         << std::string(relative ? (first ? " (reference)" : " (against exact)")
                                                 : (params.empty() ? "" : " (massless)")));
            CHECK(w.quadratic < tolerance);
            if (!(relative && first)) CHECK(w.lagrange < tolerance);
            ++variants;
        }
    }
    // The seven turbines (the operating one and the paper's floating one with
    // its loads as blocks included) and the tower test model have a joint on a
    // node.
    CHECK(variants == 8 * static_cast<int>(words.size()));
}
