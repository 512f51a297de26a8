// `approx SYMS order N` on a System: M and F replaced by their truncated Taylor
// polynomials, group after group, before any derivative is taken.
#include "passes/pass_order.hpp"
#include "passes/passes.hpp"
#include "passes/taylor.hpp"

namespace yamsc::passes {

void approximate(ir::System& s, const std::vector<ir::SymbolRef>& group, int order) {
    enter(s, ir::Pass::approximate);
    if (s.exact_F.empty()) {
        s.exact_M = s.M;
        s.exact_F = s.F;
    }
    TaylorExpansion expand(s.graph, group, order);
    for (ir::Row& row : s.M)
        for (ir::NodeId& e : row) e = expand(e);
    for (ir::NodeId& e : s.F) e = expand(e);
}

} // namespace yamsc::passes
