// The heavy symmetric top: at the steady precession rate predicted by theory,
// every acceleration of the generated equations vanishes and a simulation keeps
// the nutation angle constant.
#include "equations_fixture.hpp"

#include <yamsc/simulation.hpp>

using namespace yamsc;

namespace {
// A_tip Ω² cos θ − C ω3 Ω + m g l = 0 with ω3 = ψ' + φ' cos θ: the slow precession root.
double slow_precession(double m, double l, double A, double C, double g, double theta, double w3) {
    double At = A + m * l * l, a = At * std::cos(theta), b = -C * w3, c = m * g * l;
    return (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
}
} // namespace

TEST_CASE("heavy top: steady precession has zero accelerations") {
    auto eq = test::derive_file("models/heavy_top.mbd");
    const double m = 2.0, l = 0.3, A = 0.05, C = 0.08, g = 9.81;
    for (double theta : {0.2, 0.5, 1.0}) {
        for (double w3 : {60.0, 150.0}) {
            double Omega = slow_precession(m, l, A, C, g, theta, w3);
            double psid = w3 - Omega * std::cos(theta);
            auto v = test::evaluate(eq, {0.3, theta, 1.1}, {Omega, 0.0, psid});
            // F = M q'' with q'' = 0: F vanishes; its scale is the gyroscopic term C w3 Omega.
            double scale = C * w3 * Omega + m * g * l;
            for (double F : v.F) CHECK(std::fabs(F) < 1e-12 * scale);
            // Off the steady rate, nutation accelerates.
            auto off = test::evaluate(eq, {0.3, theta, 1.1}, {1.1 * Omega, 0.0, psid});
            CHECK(std::fabs(off.F[1]) > 1e-3 * scale);
        }
    }
}

TEST_CASE("heavy top: a simulated steady precession keeps its nutation angle") {
    auto eq = test::derive_file("models/heavy_top.mbd");
    auto c = test::compile_model(eq);
    const double theta = 0.5, w3 = 100.0;
    double Omega = slow_precession(2.0, 0.3, 0.05, 0.08, 9.81, theta, w3);
    runtime::SimulationOptions o;
    o.method = runtime::Method::cvode;
    o.rtol = 1e-11;
    o.atol = 1e-11;
    o.t_end = 10;
    o.dt = 0.1;
    o.x0 = {0, theta, 0, Omega, 0, w3 - Omega * std::cos(theta)};
    auto r = runtime::simulate(c.view, o);
    double worst = 0;
    for (std::size_t i = 0; i < r.rows(); ++i)
        worst = std::max(worst, std::fabs(r.state_row(i)[1] - theta));
    CHECK(worst < 1e-7);
    // Precession angle advanced at the predicted rate.
    CHECK(r.state_row(r.rows() - 1)[0] == doctest::Approx(Omega * 10).epsilon(1e-7));
}
