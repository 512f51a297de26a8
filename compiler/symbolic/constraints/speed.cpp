// `constraint speed`: a row written on the rates, linear in q' (the checker
// verified it), value = 0.
#include "symbolic/constraints/registry.hpp"

namespace yamsc::symbolic {

KindRows speed_rows(const model::Constraint& c, ConstraintContext& ctx) {
    return {{}, {to_ginac(c.value, ctx.symbols)}};
}

} // namespace yamsc::symbolic
