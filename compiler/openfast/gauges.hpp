#pragma once
// ElastoDyn's strain gauges (NTwGages/TwrGagNd, NBlGages/BldGagNd): the local load
// channels TwHt{k}MLxt/MLyt/MLzt and Spn{k}MLxb1/MLyb1/MLzb1 as section loads of the
// converted model (docs/openfast.md).
#include "diag/diagnostics.hpp"
#include "openfast/deck.hpp"

#include <string>
#include <vector>

namespace yamsc::openfast {

/// The `output` lines of the gauges' moment channels (empty when there are none).
/// Tower gauges need a flexible tower, blade gauges flexible blades (else a
/// warning says they are left out); blade 1's structural twist at its gauges comes
/// from its blade file.
std::string gauge_outputs(const openfast::OpenFastDeck& deck, bool flexible_tower,
                          bool flexible_blades, diag::Diagnostics& diags);

} // namespace yamsc::openfast
