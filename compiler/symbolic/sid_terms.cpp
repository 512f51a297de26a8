#include "symbolic/sid_terms.hpp"

#include <cstdio>

namespace yamsc::symbolic {

using namespace GiNaC;

ex data_number(double v) {
    if (v == 0.0) return 0;
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return exact_number(buf);
}

ElasticTerms::ElasticTerms(const model::Flexible& flex, const Symbols& symbols) : flex_(flex) {
    for (int d : flex.dofs) {
        q_.push_back(symbols.dofs()[static_cast<std::size_t>(d)].q);
        qd_.push_back(symbols.dofs()[static_cast<std::size_t>(d)].qd);
    }
}

ex ElasticTerms::at0(const sid::Taylor& t, int i, int j) {
    if (t.m0.empty()) return 0;
    return data_number(t.at0(i, j));
}

ex ElasticTerms::at(const sid::Taylor& t, int i, int j) const {
    ex value = at0(t, i, j);
    if (flex_.taylor < 1 || t.order < 1 || t.m1.empty()) return value;
    exvector terms{value};
    for (int k = 0; k < nq() && k < t.nq; ++k) {
        double c = t.at1(i, j, k);
        if (c != 0.0) terms.push_back(data_number(c) * q(k));
    }
    return add(terms);
}

NodeMotion node_motion(const model::Flexible& flex, int node_index, const Symbols& symbols) {
    ElasticTerms e(flex, symbols);
    const sid::Node& node = flex.sid->nodes[static_cast<std::size_t>(node_index)];
    NodeMotion m;
    const int nq = e.nq();
    const bool second_order = flex.taylor >= 1 && node.phi.order >= 1 && !node.phi.m1.empty();
    for (std::size_t i = 0; i < 3; ++i) {
        int ii = static_cast<int>(i);
        exvector p{ElasticTerms::at0(node.origin, ii, 0)}, pd, pdd, th, thd;
        for (int k = 0; k < nq; ++k) {
            // ∂p_i/∂q_k = Φ_ik + Σ_j ½(Φ¹_ikj + Φ¹_ijk) q_j
            exvector dp{ElasticTerms::at0(node.phi, ii, k)};
            exvector dpd; // d/dt of ∂p_i/∂q_k
            for (int j = 0; second_order && j < nq; ++j) {
                double c = 0.5 * (node.phi.at1(ii, k, j) + node.phi.at1(ii, j, k));
                if (c == 0.0) continue;
                dp.push_back(data_number(c) * e.q(j));
                dpd.push_back(data_number(c) * e.qd(j));
            }
            ex dp_k = add(dp);
            // p = origin + Σ_k (Φ_k + ½ Σ_j Φ¹ q_j) q_k, so the ½ goes on the quadratic part.
            exvector half;
            for (std::size_t t = 1; t < dp.size(); ++t) half.push_back(dp[t]);
            p.push_back((ElasticTerms::at0(node.phi, ii, k) +
                         (half.empty() ? ex(0) : ex(numeric(1, 2) * add(half)))) *
                        e.q(k));
            pd.push_back(dp_k * e.qd(k));
            if (!dpd.empty()) pdd.push_back(add(dpd) * e.qd(k));
            if (!dp_k.is_zero()) {
                auto& v = m.dp_dq[e.dof(k)];
                v[i] = dp_k;
            }
            ex psi = ElasticTerms::at0(node.psi, ii, k);
            if (!psi.is_zero()) {
                th.push_back(psi * e.q(k));
                thd.push_back(psi * e.qd(k));
                auto& v = m.dtheta_dq[e.dof(k)];
                v[i] = psi;
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
            ap.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = data_number(v);
        }
    if (!identity) m.orientation = ap;
    return m;
}

} // namespace yamsc::symbolic
