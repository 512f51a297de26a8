// regular_wave (yamsc/hydro/regular_wave.hpp) against SeaState's regular field of
// make_wave_field: the same Airy wave, evaluated exactly.
#include <yamsc/hydro/regular_wave.hpp>

#include <doctest/doctest.h>

#include <cmath>

using namespace yamsc;

TEST_CASE("regular_wave is make_wave_field's regular Airy wave, exactly") {
    runtime::hydro::WaveSettings s;
    s.kind = runtime::hydro::WaveKind::regular;
    s.water = {1025, 9.80665, 60};
    s.height = 3;
    s.period = 10;
    s.t_max = 100;
    s.dt = 0.25;
    s.phase = 0.7;
    s.direction = 0.4;
    const auto reference = runtime::hydro::make_wave_field(s);
    REQUIRE(reference->components().size() >= 1);
    runtime::hydro::WaveComponent c{};
    for (const auto& k : reference->components())
        if (std::abs(k.amplitude) > std::abs(c.amplitude)) c = k;
    const auto wave = runtime::hydro::regular_wave(s.water, c.omega, c.amplitude, s.direction);
    CHECK(wave->components()[0].wave_number == doctest::Approx(c.wave_number).epsilon(1e-12));
    for (double t : {0.0, 3.1, 47.9})
        for (const runtime::hydro::Vec3& p :
             {runtime::hydro::Vec3{0, 0, -5}, runtime::hydro::Vec3{12, -7, -30},
              runtime::hydro::Vec3{-3, 4, -59.5}}) {
            const auto a = wave->flow(t, p), b = reference->flow(t, p);
            CAPTURE(t);
            CAPTURE(p[2]);
            CHECK(wave->elevation(t, p[0], p[1]) ==
                  doctest::Approx(reference->elevation(t, p[0], p[1])).scale(1.5).epsilon(1e-10));
            for (int i = 0; i < 3; ++i) {
                CHECK(a.velocity[i] == doctest::Approx(b.velocity[i]).scale(1).epsilon(1e-10));
                CHECK(a.acceleration[i] ==
                      doctest::Approx(b.acceleration[i]).scale(1).epsilon(1e-10));
            }
            CHECK(a.dynamic_pressure ==
                  doctest::Approx(b.dynamic_pressure).scale(1e4).epsilon(1e-10));
        }
    CHECK(wave->flow(0, {0, 0, 0.5}).dynamic_pressure == 0);
    CHECK(wave->flow(0, {0, 0, -61}).velocity[0] == 0);
    CHECK_THROWS_AS(runtime::hydro::regular_wave(s.water, 0, 1), std::invalid_argument);
}
