// The Cp/Ct/Cq table from the rigid rotor: its normalization against the
// rotor's own integrals, and the round trip through ROSCO's text format.
#include "yamsc/aero/rotor_table.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <sstream>

using namespace yamsc;

namespace {

constexpr double pi = 3.14159265358979323846;

// Three straight blades of 40 m, thin-plate polar (Cl = 2 pi alpha, Cd 0.01),
// twist falling along the span.
aero::RotorInput plate_rotor() {
    aero::PolarTable t;
    t.alpha = {-pi, pi};
    t.cl = {-2 * pi * pi, 2 * pi * pi};
    t.cd = {0.01, 0.01};
    aero::Airfoil af;
    af.tables.push_back(t);
    aero::RotorInput in;
    in.airfoils.push_back(af);
    std::vector<aero::BladeNode> blade;
    for (int j = 0; j <= 10; ++j) {
        aero::BladeNode n;
        n.span = 4.0 * j;
        n.chord = 3.0 - 0.2 * j;
        n.twist = (12.0 - 1.1 * j) * pi / 180;
        blade.push_back(n);
    }
    in.blades = {blade, blade, blade};
    return in;
}

} // namespace

TEST_CASE("bem table: ROSCO's normalization of the rigid rotor's power, thrust and torque") {
    const aero::RotorInput in = plate_rotor();
    aero::RotorGeometry g;
    g.hub_radius = 1.0;
    g.precone = 0;
    g.shaft_tilt = 0; // axisymmetric: one azimuth is every azimuth
    aero::TableRequest req;
    req.tsr = {4, 7};
    req.pitch_deg = {0, 5};
    req.wind_speed = 9;
    req.rotor_radius = 41;
    req.azimuths = 2;
    const runtime::PerformanceTable t = aero::rotor_performance_table(in, g, req);

    aero::RigidRotor rotor(in, g);
    aero::OperatingPoint op;
    op.wind_speed = 9;
    op.rotor_speed = 7 * 9.0 / 41;
    op.pitch = 5 * pi / 180;
    op.azimuth = 0.3;
    const aero::RotorResult& r = rotor.evaluate(op);
    // Without tilt and precone AeroDyn's RtFld* use the same wind and radius.
    CHECK(r.r_max == doctest::Approx(41));
    CHECK(r.v_avg_xh == doctest::Approx(9));
    CHECK(r.tsr == doctest::Approx(7));
    CHECK(t.cp[3] == doctest::Approx(r.cp).epsilon(1e-9));
    CHECK(t.ct[3] == doctest::Approx(r.ct).epsilon(1e-9));
    CHECK(t.cq[3] == doctest::Approx(r.cq).epsilon(1e-9));
    CHECK(t.cp[3] == doctest::Approx(t.cq[3] * 7).epsilon(1e-12)); // Cp = TSR Cq
    CHECK(t.cp[2] > 0.2);
    CHECK(t.cp[2] < 16.0 / 27);
    CHECK(t.ct[2] > t.ct[3]); // pitching to feather unloads the rotor

    std::stringstream s;
    aero::write_performance_table(s, t, req.wind_speed, "a plate rotor");
    const runtime::PerformanceTable back = runtime::read_performance_table(s, "written");
    REQUIRE(back.tsr == t.tsr);
    REQUIRE(back.pitch_deg == t.pitch_deg);
    for (std::size_t i = 0; i < t.cp.size(); ++i) {
        CHECK(std::abs(back.cp[i] - t.cp[i]) < 1e-6);
        CHECK(std::abs(back.ct[i] - t.ct[i]) < 1e-6);
        CHECK(std::abs(back.cq[i] - t.cq[i]) < 1e-6);
    }
}
