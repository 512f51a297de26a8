// The potential-flow block closed around a floating body that heaves: the
// buoyancy holds the weight at rest, and `lin`'s heave frequency is
// sqrt(C33 / (m + A33_inf)) (the added mass solved with the structure).
#include "block_fixture.hpp"

#include <yamsc/load_block.hpp>
#include <yamsc/second_order.hpp>

#include <doctest/doctest.h>

#include <cmath>

using namespace potential_test;

namespace {

/// One DOF, heave z of a body of mass m under gravity, its mesh: 18 frame outputs
/// (r = (0, 0, z), v = (0, 0, z'), no rotation) and 6 load inputs at its origin in
/// body axes, of which the vertical force is the generalized force.
ModelView heaving_body(double m, double g) {
    ModelView v;
    v.nq = 1;
    v.nu = 6;
    v.ny = 18;
    v.dof_names = {"z"};
    v.input_names = {"fx", "fy", "fz", "mx", "my", "mz"};
    for (int i = 0; i < 18; ++i) v.output_names.push_back("frame" + std::to_string(i));
    v.rhs = [m, g](double, const double* x, const double* u, double* xd) {
        xd[0] = x[1];
        xd[1] = (u[2] - m * g) / m;
    };
    v.mass_matrix = [m](double, const double*, const double*, double* out) { out[0] = m; };
    v.forcing = [m, g](double, const double*, const double*, const double* u, double* F) {
        F[0] = u[2] - m * g;
    };
    v.jacobians = [](double, const double*, const double*, const double*, double* dq, double* dqd,
                     double* du) {
        dq[0] = dqd[0] = 0;
        for (int i = 0; i < 6; ++i) du[i] = i == 2 ? 1 : 0;
    };
    const auto frame_of = [](const double* q, const double* qd, double* y) {
        for (int i = 0; i < 18; ++i) y[i] = 0;
        y[2] = q[0];
        y[5] = qd[0];
        y[9] = y[13] = y[17] = 1; // the axes: identity
    };
    v.outputs_from_qdd = [frame_of](double, const double* q, const double* qd, const double*,
                                    const double*, double* y) { frame_of(q, qd, y); };
    v.outputs = [frame_of](double, const double* q, const double* qd, const double*, double* y) {
        frame_of(q, qd, y);
    };
    return v;
}

} // namespace

TEST_CASE("a heaving body: equilibrium at rest and the heave frequency of C33 and m + A33") {
    const double R = 5, T = 50, rho = 1025, g = 9.80665;
    const double V = M_PI * R * R * T, m = rho * V; // floating at its draft
    PotentialFlowSetup s = bare_setup();
    s.displaced_volume = V;
    s.hydrostatic[14] = rho * g * M_PI * R * R;
    s.added_mass_infinite[14] = 0.4 * m;
    s.water.density = rho;
    s.water.gravity = g;
    const ModelView v = close_blocks(heaving_body(m, g), {potential_flow_block(s)});
    const SecondOrderModel lin = second_order_model(v, {0.0}, {0.0}, std::vector<double>(6, 0.0));
    CHECK(lin.equilibrium_residual < 1e-9);
    CHECK(lin.M0[0] == doctest::Approx(1.4 * m).epsilon(1e-12));
    REQUIRE(lin.modes.size() == 1);
    const double f = std::sqrt(s.hydrostatic[14] / (1.4 * m)) / (2 * M_PI);
    CHECK(lin.modes[0].freq_hz == doctest::Approx(f).epsilon(1e-6));
}
