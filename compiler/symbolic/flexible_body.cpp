#include "symbolic/flexible_body.hpp"

#include "symbolic/sid_terms.hpp"

#include <set>

namespace yamsc::symbolic {

using namespace GiNaC;

namespace {

ex sum(exvector terms) {
    return terms.empty() ? ex(0) : ex(add(terms));
}

/// The SID's blocks evaluated at the current q, in body axes.
struct Blocks {
    ex mass;
    Vec3 md;                  // first moment of mass (mass x centre of mass)
    Mat3 J;                   // inertia about the origin
    std::vector<Vec3> Ct, Cr; // row k: ∫Φ_k dm and ∫ s × Φ_k dm (plus stiffening)
    std::vector<std::vector<ex>> Me, Ke, De;
    std::vector<ex> ksigma;
};

Blocks evaluate(const ElasticTerms& e) {
    const sid::Sid& s = e.sid();
    const int nq = e.nq();
    Blocks b;
    b.mass = e.mass();
    for (int i = 0; i < 3; ++i) {
        // md(q) = md⁰ + md¹ q + ½ qᵀ Ct¹ q: the second-order part is the axial
        // shortening whose derivative Ct(q) = ∂md/∂q carries K_gt (see docs/theory.md).
        exvector md{e.at("mdCM", s.md_cm, i, 0)};
        for (int k = 0; k < e.nq(); ++k)
            for (int l = 0; l < e.nq(); ++l) {
                ex c = e.at1("Ct", s.Ct, k, i, l);
                if (!c.is_zero()) md.push_back(numeric(1, 2) * c * e.q(k) * e.q(l));
            }
        b.md[static_cast<std::size_t>(i)] = sum(md);
        for (int j = 0; j < 3; ++j)
            b.J.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = e.at("J", s.J, i, j);
    }
    b.Ct.resize(static_cast<std::size_t>(nq));
    b.Cr.resize(static_cast<std::size_t>(nq));
    for (int k = 0; k < nq; ++k) {
        auto uk = static_cast<std::size_t>(k);
        for (int a = 0; a < 3; ++a) {
            b.Ct[uk][static_cast<std::size_t>(a)] = e.at("Ct", s.Ct, k, a);
            b.Cr[uk][static_cast<std::size_t>(a)] = e.at("Cr", s.Cr, k, a);
        }
        b.ksigma.push_back(e.at("ksigma", s.ksigma, k, 0));
        b.Me.emplace_back();
        b.Ke.emplace_back();
        b.De.emplace_back();
        for (int l = 0; l < nq; ++l) {
            b.Me.back().push_back(e.at("Me", s.Me, k, l));
            b.Ke.back().push_back(e.at("Ke", s.Ke, k, l));
            b.De.back().push_back(e.at("De", s.De, k, l));
        }
    }
    return b;
}

/// The generalized momentum directions of one coordinate: what multiplies q''_s in
/// the translational, rotational and elastic rows of eq. A1.
struct Rows {
    Vec3 x, theta;
    std::vector<ex> e;
};

/// Everything the body adds, at the current q: the momentum rows of the
/// coordinates that move it and its forces without q''.
struct Terms {
    std::set<int> coords;
    std::map<int, int> mode_of;
    std::map<int, Rows> rows;
    Vec3 fx, ft;
    std::vector<ex> fe;
    FrameState frame;
    Blocks blocks;
    Vec3 jv(int r) const {
        auto it = frame.Jv.find(r);
        return it == frame.Jv.end() ? Vec3{} : it->second;
    }
    Vec3 jw(int r) const {
        auto it = frame.Jw.find(r);
        return it == frame.Jw.end() ? Vec3{} : it->second;
    }
};

Terms flexible_terms(const model::Body& body, const FrameState& f, const Vec3& g,
                     const Symbols& symbols) {
    ElasticTerms el(body, symbols);
    const sid::Sid& s = el.sid();
    const int nq = el.nq();
    const auto un = static_cast<std::size_t>(nq);
    Terms out;
    out.blocks = evaluate(el);
    const Blocks& b = out.blocks;
    out.frame = f;

    // Coordinates that move this body: its frame's and its own modes.
    std::set<int>& coords = out.coords;
    for (const auto& [r, v] : f.Jv) coords.insert(r);
    for (const auto& [r, v] : f.Jw) coords.insert(r);
    std::map<int, int>& mode_of = out.mode_of;
    for (int k = 0; k < nq; ++k) {
        coords.insert(el.dof(k));
        mode_of[el.dof(k)] = k;
    }

    // Momentum rows: M_body [Jv_s, Jω_s, Je_s] (eq. 18, A2-A7).
    for (int r : coords) {
        Vec3 v = out.jv(r), w = out.jw(r);
        Rows row;
        row.x = b.mass * v + cross(w, b.md); // Mxx v + Mxθ ω, Mxθ = -m d~
        row.theta = cross(b.md, v) + b.J * w;
        row.e.resize(un);
        for (int k = 0; k < nq; ++k) {
            auto uk = static_cast<std::size_t>(k);
            row.e[uk] = dot(b.Ct[uk], v) + dot(b.Cr[uk], w);
        }
        auto mode = mode_of.find(r);
        if (mode != mode_of.end()) {
            auto m = static_cast<std::size_t>(mode->second);
            Vec3 ct, cr;
            for (std::size_t a = 0; a < 3; ++a) {
                ct[a] = b.Ct[m][a];
                cr[a] = b.Cr[m][a];
            }
            row.x = row.x + ct;
            row.theta = row.theta + cr;
            for (std::size_t k = 0; k < un; ++k) row.e[k] = row.e[k] + b.Me[k][m];
        }
        out.rows.emplace(r, std::move(row));
    }

    // Forces without q'': inertial (eq. 12-14 with A8-A10), gravity (A17-A19),
    // elastic (A16). a, α are the frame's bias accelerations.
    const Vec3& w = f.w;
    Vec3 ctq; // Ctᵀ q'
    for (int k = 0; k < nq; ++k) ctq = ctq + el.qd(k) * b.Ct[static_cast<std::size_t>(k)];
    // d/dt(Ct)ᵀ q' = Σ_kl Ct¹_k,l q'_k q'_l completes the acceleration of the mass centre.
    Vec3 ct_dot;
    for (int a = 0; a < 3; ++a) {
        exvector t;
        for (int k = 0; k < nq; ++k)
            for (int l = 0; l < nq; ++l) {
                ex c = el.at1("Ct", s.Ct, k, a, l);
                if (!c.is_zero()) t.push_back(c * el.qd(k) * el.qd(l));
            }
        ct_dot[static_cast<std::size_t>(a)] = sum(t);
    }
    Vec3 k_wx = 2 * cross(w, ctq) + cross(w, cross(w, b.md)) + ct_dot;
    // Σ_j Gr_j q'_j and Σ_j Ge_j q'_j (Gr: 3 x 3nq, Ge: nq x 3nq, block j = columns 3j..3j+2).
    Mat3 gr;
    std::vector<Vec3> ge_rows(un);
    for (int j = 0; j < nq; ++j)
        for (int c = 0; c < 3; ++c) {
            for (int i = 0; i < 3; ++i) {
                ex x = el.at("Gr", s.Gr, i, 3 * j + c);
                auto& cell = gr.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)];
                if (!x.is_zero()) cell = cell + x * el.qd(j);
            }
            for (int k = 0; k < nq; ++k) {
                ex x = el.at("Ge", s.Ge, k, 3 * j + c);
                auto& cell = ge_rows[static_cast<std::size_t>(k)][static_cast<std::size_t>(c)];
                if (!x.is_zero()) cell = cell + x * el.qd(j);
            }
        }
    Vec3 k_wt = cross(w, b.J * w) + gr * w;
    const std::array<ex, 6> omega2{w[0] * w[0], w[1] * w[1], w[2] * w[2],
                                   w[0] * w[1], w[1] * w[2], w[0] * w[2]}; // eq. A15
    out.fx = b.mass * (g - f.a) - cross(f.alpha, b.md) - k_wx;
    out.ft = cross(b.md, g - f.a) - b.J * f.alpha - k_wt;
    out.fe.resize(un);
    for (int k = 0; k < nq; ++k) {
        auto uk = static_cast<std::size_t>(k);
        exvector t{dot(b.Ct[uk], g - f.a), -dot(b.Cr[uk], f.alpha), -dot(ge_rows[uk], w),
                   -b.ksigma[uk]};
        for (std::size_t c = 0; c < 6; ++c) {
            ex oe = el.at("Oe", s.Oe, k, static_cast<int>(c));
            if (!oe.is_zero()) t.push_back(-oe * omega2[c]);
        }
        for (int l = 0; l < nq; ++l) {
            auto ul = static_cast<std::size_t>(l);
            if (!b.Ke[uk][ul].is_zero()) t.push_back(-b.Ke[uk][ul] * el.q(l));
            if (!b.De[uk][ul].is_zero()) t.push_back(-b.De[uk][ul] * el.qd(l));
        }
        out.fe[uk] = sum(t);
    }
    return out;
}

/// The momentum rows weighted by the accelerations a_s.
Rows weighted_rows(const Terms& terms, const std::vector<ex>& a, std::size_t n_modes) {
    Rows A;
    A.e.assign(n_modes, ex(0));
    for (const auto& [s_, row] : terms.rows) {
        const ex& as = a[static_cast<std::size_t>(s_)];
        A.x = A.x + as * row.x;
        A.theta = A.theta + as * row.theta;
        for (std::size_t k = 0; k < n_modes; ++k) A.e[k] = A.e[k] + as * row.e[k];
    }
    return A;
}

} // namespace

BodyTerms flexible_body_terms(const model::Body& body, const FrameState& f, const Vec3& g,
                              const Symbols& symbols) {
    const Terms terms = flexible_terms(body, f, g, symbols);
    const Blocks& b = terms.blocks;
    BodyTerms out;
    out.inertia.mass = b.mass;
    out.inertia.md = b.md;
    out.inertia.J = b.J;
    out.load = {terms.fx, terms.ft};
    out.modes.resize(terms.fe.size());
    for (const auto& [dof, k_] : terms.mode_of) {
        const auto k = static_cast<std::size_t>(k_);
        ModeTerms& mode = out.modes[k];
        mode.dof = dof;
        mode.ct = b.Ct[k];
        mode.cr = b.Cr[k];
        mode.force = terms.fe[k];
    }
    out.Me = b.Me;
    return out;
}

std::pair<Vec3, Vec3> flexible_body_wrench(const model::Body& body, const FrameState& f,
                                           const Vec3& g, const Symbols& symbols,
                                           const std::vector<ex>& qdd) {
    const Terms terms = flexible_terms(body, f, g, symbols);
    // The momentum rate of the whole body is its momentum rows times q'' plus the
    // q''-free part already in f_x, f_θ (with gravity): eq. A1's first two rows.
    const Rows A = weighted_rows(terms, qdd, terms.fe.size());
    return {terms.fx - A.x, terms.ft - A.theta};
}

} // namespace yamsc::symbolic
