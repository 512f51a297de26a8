#pragma once
// A flexible body's Standard Input Data as GiNaC expressions of its elastic
// coordinates: Taylor blocks T(q) = T0 + Σ T1_k q_k (paper eq. D2) and the motion
// of its nodes, which bodies attached to the node follow.
#include "model/model.hpp"
#include "symbolic/expressions.hpp"

#include <map>
#include <optional>

namespace yamsc::symbolic {

class ElasticTerms {
public:
    ElasticTerms(const model::Body& body, const Symbols& symbols);

    int nq() const { return static_cast<int>(q_.size()); }
    const sid::Sid& sid() const { return *flex_.sid; }
    /// Whether first-order Taylor terms are used (`taylor = 1`).
    bool first_order() const { return flex_.taylor >= 1; }
    /// DOF index of mode k.
    int dof(int k) const { return flex_.dofs[static_cast<std::size_t>(k)]; }
    const GiNaC::ex& q(int k) const { return q_[static_cast<std::size_t>(k)]; }
    const GiNaC::ex& qd(int k) const { return qd_[static_cast<std::size_t>(k)]; }

    /// The body's mass: a number, or its parameter for `symbolic modes`.
    GiNaC::ex mass() const;
    /// Entry (i, j) of SID block `term` (of node `node` if >= 0) at the current q:
    /// T0 + Σ T1_k q_k, the first-order part only with `taylor = 1`.
    GiNaC::ex at(const std::string& term, const sid::Taylor& t, int i, int j, int node = -1) const;
    /// The constant part T0(i, j), and a first-order coefficient T1(i, j, k) (zero
    /// when the body uses order 0).
    GiNaC::ex at0(const std::string& term, const sid::Taylor& t, int i, int j, int node = -1) const;
    GiNaC::ex at1(const std::string& term, const sid::Taylor& t, int i, int j, int k,
                  int node = -1) const;

private:
    /// A data value as a number, or as its parameter for symbolic bodies.
    GiNaC::ex value(double v, const std::string& name) const;

    const model::Body& body_;
    const model::Flexible& flex_;
    const Symbols& symbols_;
    std::vector<GiNaC::ex> q_, qd_;
};

/// An exact GiNaC number for a double read from data: its 17 significant digits
/// (%.17g, which read back as the same double; the golden files depend on them).
GiNaC::ex data_number(double v);

/// How a node moves relative to its body: p = origin + Φ q + ½ qᵀ Φ¹ q (the
/// second-order term carries the geometric stiffening of loads at the node),
/// small rotation θ = Ψ q, and the node frame's constant orientation.
struct NodeMotion {
    Vec3 p, pd, pdd;               // position, rate, bias acceleration (body axes)
    std::map<int, Vec3> dp_dq;     // ∂p/∂q_r
    Vec3 theta, thetad;            // elastic rotation and its rate
    std::map<int, Vec3> dtheta_dq; // ∂θ/∂q_r
    std::optional<Mat3> orientation;
};

NodeMotion node_motion(const model::Body& body, int node, const Symbols& symbols);

} // namespace yamsc::symbolic
