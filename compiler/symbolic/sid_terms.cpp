#include "symbolic/sid_terms.hpp"

#include <cmath>
#include <cstdio>

namespace yamsc::symbolic {

using namespace GiNaC;

ex data_number(double v) {
    if (v == 0.0) return 0;
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return exact_number(buf);
}

ElasticTerms::ElasticTerms(const model::Body& body, const Symbols& symbols)
    : body_(body), flex_(*body.flex), symbols_(symbols) {
    for (int d : flex_.dofs) {
        q_.push_back(symbols.dofs()[static_cast<std::size_t>(d)].q);
        qd_.push_back(symbols.dofs()[static_cast<std::size_t>(d)].qd);
    }
}

ex ElasticTerms::value(double v, const std::string& name) const {
    if (v == 0.0) return 0;
    if (flex_.symbolic) return symbols_.lookup(name, 0);
    if (!std::isfinite(v)) throw diag::InternalError("a SID value without a number: " + name);
    return data_number(v);
}

ex ElasticTerms::mass() const {
    return value(sid().mass, model::shape_parameter_name(body_.name, "mass", 0, 0));
}

ex ElasticTerms::at0(const std::string& term, const sid::Taylor& t, int i, int j, int node) const {
    if (t.m0.empty()) return 0;
    return value(t.at0(i, j), model::shape_parameter_name(body_.name, term, i, j, -1, node));
}

ex ElasticTerms::at1(const std::string& term, const sid::Taylor& t, int i, int j, int k,
                     int node) const {
    if (!first_order() || t.order < 1 || t.m1.empty() || k >= t.nq) return 0;
    return value(t.at1(i, j, k), model::shape_parameter_name(body_.name, term, i, j, k, node));
}

ex ElasticTerms::at(const std::string& term, const sid::Taylor& t, int i, int j, int node) const {
    exvector terms{at0(term, t, i, j, node)};
    for (int k = 0; k < nq(); ++k) {
        ex c = at1(term, t, i, j, k, node);
        if (!c.is_zero()) terms.push_back(c * q(k));
    }
    return add(terms);
}

NodeMotion node_motion(const model::Body& body, int node_index, const Symbols& symbols) {
    ElasticTerms e(body, symbols);
    const sid::Node& node = e.sid().nodes[static_cast<std::size_t>(node_index)];
    const int id = node.id;
    NodeMotion m;
    const int nq = e.nq();
    for (std::size_t i = 0; i < 3; ++i) {
        int ii = static_cast<int>(i);
        exvector p{e.at0("origin", node.origin, ii, 0, id)}, pd, pdd, th, thd;
        for (int k = 0; k < nq; ++k) {
            // ∂p_i/∂q_k = Φ_ik + Σ_j ½(Φ¹_ikj + Φ¹_ijk) q_j
            ex phi = e.at0("phi", node.phi, ii, k, id);
            exvector dp{phi}, half, dpd; // dpd: d/dt of ∂p_i/∂q_k
            for (int j = 0; j < nq; ++j) {
                ex c = numeric(1, 2) * (e.at1("phi", node.phi, ii, k, j, id) +
                                        e.at1("phi", node.phi, ii, j, k, id));
                if (c.is_zero()) continue;
                dp.push_back(c * e.q(j));
                half.push_back(c * e.q(j));
                dpd.push_back(c * e.qd(j));
            }
            ex dp_k = add(dp);
            // p = origin + Σ_k (Φ_k + ½ Σ_j Φ¹ q_j) q_k: the ½ goes on the quadratic part.
            p.push_back((phi + (half.empty() ? ex(0) : ex(numeric(1, 2) * add(half)))) * e.q(k));
            pd.push_back(dp_k * e.qd(k));
            if (!dpd.empty()) pdd.push_back(add(dpd) * e.qd(k));
            if (!dp_k.is_zero()) m.dp_dq[e.dof(k)][i] = dp_k;
            ex psi = e.at0("psi", node.psi, ii, k, id);
            if (!psi.is_zero()) {
                th.push_back(psi * e.q(k));
                thd.push_back(psi * e.qd(k));
                m.dtheta_dq[e.dof(k)][i] = psi;
            }
        }
        m.p[i] = add(p);
        m.pd[i] = pd.empty() ? ex(0) : ex(add(pd));
        m.pdd[i] = pdd.empty() ? ex(0) : ex(add(pdd));
        m.theta[i] = th.empty() ? ex(0) : ex(add(th));
        m.thetad[i] = thd.empty() ? ex(0) : ex(add(thd));
    }
    // The node frame's orientation (AP0), when it is not the body's.
    bool identity = true;
    Mat3 ap;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double v = node.ap.m0.empty() ? (i == j) : node.ap.at0(i, j);
            if (v != (i == j ? 1.0 : 0.0)) identity = false;
            ap.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
                node.ap.m0.empty() ? ex(i == j ? 1 : 0) : e.at0("AP", node.ap, i, j, id);
        }
    if (!identity) m.orientation = ap;
    return m;
}

} // namespace yamsc::symbolic
