#include "analysis/sea_state_setup.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace yamsc::analysis {

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi / 180;
} // namespace

runtime::hydro::WaveSettings wave_settings(const seastate::Input& in,
                                           const runtime::hydro::Water& defaults,
                                           diag::Diagnostics& diags, double default_msl2swl) {
    using diag::Kind;
    using runtime::hydro::WaveKind;
    runtime::hydro::WaveSettings s;
    s.water.gravity = defaults.gravity;
    s.water.density = in.water_density.value_or(defaults.density);
    s.water.depth = in.water_depth.value_or(defaults.depth) + in.msl2swl.value_or(default_msl2swl);
    if (!(s.water.depth > 0))
        diags.error(Kind::InvalidValue, in.location("WtrDpth"),
                    "the water depth below the still-water level (WtrDpth + MSL2SWL) must be > 0");
    if (!(s.water.density > 0))
        diags.error(Kind::InvalidValue, in.location("WtrDens"), "WtrDens must be > 0");

    switch (in.wave_mod) {
    case seastate::WaveKind::still:
        s.kind = WaveKind::still;
        return s;
    case seastate::WaveKind::regular:
        s.kind = WaveKind::regular;
        break;
    case seastate::WaveKind::irregular:
        s.kind = WaveKind::irregular;
        break;
    default:
        diags.warning(Kind::NotSupported, in.location("WaveMod"),
                      "WaveMod " + std::to_string(static_cast<int>(in.wave_mod)) +
                          " is not modelled: still water is used");
        return s;
    }
    s.height = in.wave_hs;
    s.period = in.wave_tp;
    s.direction = in.wave_dir_deg * deg;
    s.t_max = in.wave_tmax;
    s.dt = in.wave_dt;
    s.seed1 = in.seed1;
    s.seed2 = in.seed2;
    s.ranlux = in.generator == seastate::RandomGenerator::ranlux;
    s.normal_amplitudes = in.normal_amplitudes;
    s.stretching = static_cast<runtime::hydro::Stretching>(static_cast<int>(in.stretching));
    if (in.regular_user_phase) s.phase = in.wave_phase_deg * deg;

    auto check = [&](bool ok, const char* key, const std::string& message) {
        if (!ok) diags.error(Kind::InvalidValue, in.location(key), message);
    };
    check(s.dt > 0, "WaveDT", "WaveDT must be > 0");
    check(s.t_max > 0, "WaveTMax", "WaveTMax must be > 0");
    check(s.height > 0, "WaveHs", "WaveHs must be > 0");
    check(s.period > 0, "WaveTp", "WaveTp must be > 0");
    if (s.kind == WaveKind::regular) {
        // SeaState puts the wave on its grid's nearest frequency and gives still water
        // when that is the first one, beyond the Nyquist frequency or zero.
        if (s.dt > 0 && s.t_max > 0 && s.period > 0) {
            const int n = runtime::hydro::wave_time_steps(s.t_max, s.dt);
            const long m = std::lround(n * s.dt / s.period);
            check(m > 1 && m < n / 2, "WaveTp",
                  "the regular wave's period must lie between 2 WaveDT and WaveTMax / 2");
        }
        return s;
    }
    if (in.peak_shape) {
        s.peak_shape = *in.peak_shape;
        check(*in.peak_shape >= 1 && *in.peak_shape <= 7, "WavePkShp", "WavePkShp must be 1 to 7");
    }
    s.low_cutoff = in.low_cutoff;
    s.high_cutoff = in.high_cutoff;
    check(s.low_cutoff >= 0, "WvLowCOff", "WvLowCOff must be >= 0");
    // SeaState lowers WvHiCOff to the Nyquist frequency pi / WaveDT.
    if (s.dt > 0) s.high_cutoff = std::min(s.high_cutoff, pi / s.dt);
    check(s.low_cutoff < s.high_cutoff, "WvLowCOff", "WvLowCOff must be less than WvHiCOff");
    return s;
}

} // namespace yamsc::analysis
