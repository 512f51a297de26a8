// Energy conservation of a conservative 3D system over 100 s with CVODE at
// tight tolerance: T = q'ᵀ M q' / 2 from the generated mass matrix, V from the
// model's own output.
#include "equations_fixture.hpp"

#include <yamsc/simulation.hpp>

using namespace yamsc;

TEST_CASE("tumbling 3D chain: energy is conserved over 100 s") {
    auto eq = test::derive_file("tests/physics/models/tumbling.mbd");
    auto c = test::compile_model(eq);
    const auto& v = c.view;
    const int nq = v.nq;
    runtime::SimulationOptions o;
    o.method = runtime::Method::cvode;
    o.rtol = 1e-12;
    o.atol = 1e-12;
    o.t_end = 100;
    o.dt = 0.5;
    o.x0 = {0.8, -0.4, 1.2, 0.3, 0.05, 1.5, -2.0, 0.7, 3.0, 0.4};
    REQUIRE(static_cast<int>(o.x0.size()) == 2 * nq);
    auto r = runtime::simulate(v, o);
    auto energy = [&](std::size_t row) {
        return test::kinetic_energy(v, r.time[row], r.state_row(row)) + r.output_row(row)[0];
    };
    const double E0 = energy(0);
    const double T0 = test::kinetic_energy(v, 0, o.x0.data());
    double drift = 0;
    for (std::size_t i = 0; i < r.rows(); ++i) drift = std::max(drift, std::fabs(energy(i) - E0));
    const double scale = std::max(std::fabs(E0), T0);
    MESSAGE("energy " << E0 << " J, max drift " << drift << " J, relative " << drift / scale);
    CHECK(drift / scale < 1e-7);
    // The motion is not trivial: the configuration moved far from the start.
    CHECK(std::fabs(r.state_row(r.rows() - 1)[0] - o.x0[0]) +
              std::fabs(r.state_row(r.rows() - 1)[2] - o.x0[2]) >
          0.1);
}
