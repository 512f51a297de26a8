#pragma once
// ElastoDyn's strain gauges as its main file lists them (NTwGages/TwrGagNd,
// NBlGages/BldGagNd); compiler/openfast/gauges.hpp turns them into load channels.
#include "diag/diagnostics.hpp"

#include <vector>

namespace yamsc::openfast {

/// The gauge nodes of the ElastoDyn file (element numbers, 1-based), as many as
/// NTwGages and NBlGages say; empty lists when they are 0.
struct GaugeNodes {
    std::vector<int> tower, blade;
};
GaugeNodes read_gauge_nodes(const diag::SourceFile& elastodyn);

} // namespace yamsc::openfast
