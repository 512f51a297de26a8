// `constraint relation`: an algebraic relation of coordinates, t, inputs and
// parameters, value = 0.
#include "symbolic/constraints/registry.hpp"

namespace yamsc::symbolic {

KindRows relation_rows(const model::Constraint& c, ConstraintContext& ctx) {
    return {{to_ginac(c.value, ctx.symbols)}, {}};
}

} // namespace yamsc::symbolic
