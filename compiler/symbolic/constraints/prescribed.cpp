// `constraint prescribed`: q_k - value(t, u, p) = 0. Its row of B is e_k, so its
// reaction is the generalized force that holds the coordinate.
#include "symbolic/constraints/registry.hpp"

namespace yamsc::symbolic {

KindRows prescribed_rows(const model::Constraint& c, ConstraintContext& ctx) {
    const Dof& d = ctx.symbols.dofs()[static_cast<std::size_t>(c.coordinate)];
    return {{d.q - to_ginac(c.value, ctx.symbols)}, {}};
}

} // namespace yamsc::symbolic
