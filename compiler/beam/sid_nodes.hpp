#pragma once
// The SID nodes of a beam: one per integration station, root to tip.
#include "beam/sampled_beam.hpp"
#include "sid/sid.hpp"

namespace yamsc::beam {

/// Appends the nodes (ids 1..n) to `sid` (sid.nq set).
void add_nodes(const SampledBeam& b, sid::Sid& sid);

} // namespace yamsc::beam
