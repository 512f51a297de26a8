#pragma once
// One Airy wave of a given complex amplitude at a frequency, evaluated exactly
// (no time grid, no random phase): what a frequency-domain analysis samples the
// hydrodynamic loads in (docs/hydrodynamics.md, "Frequency-domain response").
// Elevation Re(a exp(i (w t - k (x cos(dir) + y sin(dir))))), finite-depth
// kinematics, zero above the still-water level and below the seabed, as
// make_wave_field's fields without stretching.
#include "yamsc/hydro/waves.hpp"

#include <complex>
#include <memory>

namespace yamsc::runtime::hydro {

/// Throws std::invalid_argument for omega <= 0 or a depth <= 0.
std::shared_ptr<const WaveField> regular_wave(const Water& water, double omega,
                                              std::complex<double> amplitude, double direction = 0);

} // namespace yamsc::runtime::hydro
