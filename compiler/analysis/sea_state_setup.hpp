#pragma once
// A SeaState input file as the runtime's wave field settings
// (yamsc/hydro/waves.hpp): degrees to radians, "default" entries from the deck,
// SeaState's own adjustments (the high cut-off at pi / WaveDT, the water depth below
// the still-water level). docs/hydrodynamics.md ("Waves") lists each convention.
#include "diag/diagnostics.hpp"
#include "seastate/seastate_input.hpp"
#include "yamsc/hydro/waves.hpp"

namespace yamsc::analysis {

/// `defaults` are the deck's (the .fst's WtrDens, WtrDpth, Gravity) for the entries
/// written "default"; `default_msl2swl` the .fst's MSL2SWL. The depth of the result is
/// below the still-water level (WtrDpth + MSL2SWL, SeaState's EffWtrDpth). Values
/// SeaState refuses are errors at their entry; wave kinds not modelled give still
/// water with a warning at WaveMod.
runtime::hydro::WaveSettings wave_settings(const seastate::Input& input,
                                           const runtime::hydro::Water& defaults,
                                           diag::Diagnostics& diags, double default_msl2swl = 0);

} // namespace yamsc::analysis
