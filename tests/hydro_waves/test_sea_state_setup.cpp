// SeaState's file as wave settings: the OC3-Hywind file of data/hydro read and
// converted, degrees to radians, the deck's defaults, SeaState's own adjustments.
#include "analysis/sea_state_setup.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace yamsc;
using runtime::hydro::WaveKind;

namespace {
constexpr double pi = 3.14159265358979323846;

seastate::Input jonswap_input() {
    seastate::Input in;
    in.wave_mod = seastate::WaveKind::irregular;
    in.wave_tmax = 3630;
    in.wave_dt = 0.25;
    in.wave_hs = 6;
    in.wave_tp = 10;
    in.low_cutoff = 0.1;
    in.high_cutoff = 500;
    in.wave_dir_deg = 30;
    in.seed1 = 123456789;
    in.generator = seastate::RandomGenerator::ranlux;
    in.normal_amplitudes = true;
    in.stretching = seastate::Stretching::wheeler;
    return in;
}
} // namespace

TEST_CASE("SeaState's OC3-Hywind file: JONSWAP, RANLUX, the deck's water") {
    diag::Diagnostics diags;
    const auto in = seastate::read_seastate_input(
        std::filesystem::path(YAMSC_SOURCE_DIR) / "tests/data/hydro/oc3_sea_state.dat", diags);
    REQUIRE(in);
    diag::Diagnostics d2;
    const runtime::hydro::Water deck{1025, 9.80665, 320};
    const auto s = analysis::wave_settings(*in, deck, d2);
    CHECK_FALSE(d2.has_errors());
    CHECK(s.kind == WaveKind::irregular);
    CHECK(s.water.depth == 320);
    CHECK(s.water.density == 1025);
    CHECK(s.height == 6);
    CHECK(s.period == 10);
    CHECK_FALSE(s.peak_shape);
    CHECK(s.seed1 == 123456789);
    CHECK(s.ranlux);
    CHECK(s.normal_amplitudes);
    CHECK(s.high_cutoff == doctest::Approx(pi / 0.25)); // 500 lowered to pi / WaveDT
    CHECK(runtime::hydro::make_wave_field(s)->period() == 600);
}

TEST_CASE("SeaState's entries: degrees, MSL2SWL, stretching, seeds") {
    auto in = jonswap_input();
    in.water_depth = 200;
    in.msl2swl = 1.5;
    diag::Diagnostics diags;
    const auto s = analysis::wave_settings(in, {1000, 9.81, 320}, diags);
    CHECK_FALSE(diags.has_errors());
    CHECK(s.water.depth == 201.5);
    CHECK(s.water.density == 1000);
    CHECK(s.water.gravity == 9.81);
    CHECK(s.direction == doctest::Approx(pi / 6));
    CHECK(s.stretching == runtime::hydro::Stretching::wheeler);
    CHECK(s.low_cutoff == 0.1);
    CHECK(s.t_max == 3630);

    in.wave_mod = seastate::WaveKind::regular;
    in.regular_user_phase = true;
    in.wave_phase_deg = 90;
    const auto r = analysis::wave_settings(in, {}, diags);
    CHECK(r.kind == WaveKind::regular);
    REQUIRE(r.phase);
    CHECK(*r.phase == doctest::Approx(pi / 2));
}

TEST_CASE("SeaState's refusals are errors at their entry; other wave kinds warn") {
    auto in = jonswap_input();
    in.peak_shape = 9;
    in.wave_hs = 0;
    diag::Diagnostics diags;
    analysis::wave_settings(in, {}, diags);
    CHECK(diags.error_count() == 2);

    in = jonswap_input();
    in.wave_mod = seastate::WaveKind::regular;
    in.wave_tp = 4000; // beyond WaveTMax / 2: SeaState's still water
    diag::Diagnostics d2;
    analysis::wave_settings(in, {}, d2);
    CHECK(d2.error_count() == 1);

    in = jonswap_input();
    in.wave_mod = seastate::WaveKind::white_noise;
    diag::Diagnostics d3;
    const auto s = analysis::wave_settings(in, {}, d3);
    CHECK_FALSE(d3.has_errors());
    CHECK(d3.all().size() == 1);
    CHECK(s.kind == WaveKind::still);
}
