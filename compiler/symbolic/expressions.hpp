#pragma once
// From checked-model expressions to GiNaC: the symbols of a model (t, q, q', q'',
// input channels, parameters), exact numbers, and time derivatives by the chain
// rule over q, q', u and their derivatives.
#include "model/model.hpp"
#include "symbolic/dag.hpp"
#include "symbolic/equations.hpp"
#include "symbolic/vec3.hpp"

#include <functional>
#include <map>
#include <memory>

namespace yamsc::symbolic {

/// The symbols of one model, created once in a fixed order.
class Symbols {
public:
    explicit Symbols(const model::Model& m);

    const GiNaC::symbol& t() const { return t_; }
    const std::vector<Dof>& dofs() const { return dofs_; }
    const std::vector<InputChannel>& inputs() const { return channels_; }
    const std::vector<Parameter>& params() const { return params_; }

    /// The symbol a name with `primes` stands for (q, q', q'', u, u', p, t).
    GiNaC::ex lookup(const std::string& name, int primes) const;

    /// d/dt e = Σ ∂e/∂q q' + ∂e/∂q' q'' + Σ ∂e/∂u⁽ʲ⁾ u⁽ʲ⁺¹⁾ + ∂e/∂t. With
    /// `with_qdd == false` the q'' terms are left out (the "bias" part).
    GiNaC::ex time_derivative(const GiNaC::ex& e, bool with_qdd);
    /// ∂e/∂t + Σ ∂e/∂u⁽ʲ⁾ u⁽ʲ⁺¹⁾: the part of d/dt e not through q and q'.
    GiNaC::ex explicit_time_derivative(const GiNaC::ex& e);

    /// ∂e/∂s, memoised per symbol across calls.
    GiNaC::ex diff(const GiNaC::ex& e, const GiNaC::symbol& s);

private:
    void explicit_time_terms(const GiNaC::ex& e, GiNaC::exvector& terms);

    GiNaC::symbol t_;
    std::vector<Dof> dofs_;
    std::vector<InputChannel> channels_;
    std::vector<int> next_channel_; // index of the derivative of each channel, -1 if none
    std::vector<Parameter> params_;
    std::map<std::string, GiNaC::ex> by_name_[3]; // by number of primes
    std::map<std::string, std::unique_ptr<Differentiator>> diffs_;
};

/// Vector value of a kinematic call in an output: position(b), velocity(b), ...
using KinematicsHook = std::function<Vec3(const std::string& function, const model::Expr& target)>;

/// Converts a scalar expression (checked) to GiNaC.
GiNaC::ex to_ginac(const model::Expr& e, const Symbols& symbols, const KinematicsHook& kin = {});
/// Converts a vector expression to its three components.
Vec3 to_ginac_vec(const model::Expr& e, const Symbols& symbols, const KinematicsHook& kin = {});
Vec3 to_ginac(const model::Vec& v, const Symbols& symbols);

/// The exact rational value of a decimal literal such as "1.5e-3".
GiNaC::ex exact_number(const std::string& text);

} // namespace yamsc::symbolic
