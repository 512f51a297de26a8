#pragma once
// `yamsc lin MODEL --hydro F --rao FILE.csv [--sea-state F] [--plot FILE.svg]`:
// the model's RAOs (analysis/wave_response.hpp) written as CSV and SVG, and with
// a JONSWAP sea the response spectra's standard deviations
// (docs/hydrodynamics.md, "Frequency-domain response"; docs/cli.md).
#include "analysis/loaded_model.hpp"
#include "driver/commands.hpp"

#include <iosfwd>
#include <vector>

namespace yamsc::analysis {

/// Writes o.rao (and o.plot) for the point (q, u); the table to `out`.
int rao_report(const Loaded& l, const driver::LinOptions& o, const std::vector<double>& q,
               const std::vector<double>& u, std::ostream& out, std::ostream& err);

} // namespace yamsc::analysis
