#pragma once
// The outputs as two routines: outputs_from_qdd reads q'' from its argument,
// and outputs calls it with the q'' of rhs itself. A simulation that stores a
// row where the integrator has just evaluated rhs passes that q'' on instead
// of solving M q'' = F a second time, and still gets outputs' numbers to the
// last bit: the two routines share one body, and outputs takes its q'' from
// the very code of rhs (a second solve printed on its own could round
// differently).
#include "codegen/module.hpp"

#include <vector>

namespace yamsc::codegen {

/// Appends outputs_from_qdd(t, q, qd, qdd, u, p, y) (the outputs `y` with q''
/// bound to its argument qdd) and then outputs(t, q, qd, u, p, y). When
/// `accelerations` (some output reads q''), outputs copies [q, q'] into a
/// local x, calls rhs(t, x, u, p, xdot) (the module must have rhs) and
/// outputs_from_qdd with xdot + nq; otherwise it calls outputs_from_qdd with
/// q'' = 0, which the outputs do not read.
void add_output_routines(Graph& g, const std::vector<NodeId>& y, int nq, bool accelerations,
                         const Options& options, std::vector<Routine>& routines);

} // namespace yamsc::codegen
