// yamsc/frequency_response.hpp against closed forms: a heaving cylinder's RAO,
// its resonance and low-frequency limit, a 2-DOF solve by Cramer's rule, and the
// variance of a lightly damped oscillator in white noise.
#include <yamsc/frequency_response.hpp>

#include <doctest/doctest.h>

#include <cmath>

namespace {

using yamsc::runtime::Complex;
using yamsc::runtime::frequency_response;
using yamsc::runtime::FrequencyTerms;
using yamsc::runtime::LinearDynamics;

// A vertical cylinder of radius 5 m and draft 20 m heaving (rho 1025, g 9.80665):
// its mass the displaced water's, an added mass of 30 % of it, a linear damping.
constexpr double rho = 1025, g = 9.80665, radius = 5, draft = 20;
const double area = M_PI * radius * radius;
const double mass = rho * area * draft, added = 0.3 * mass, stiffness = rho * g * area,
             damping = 2e5;

LinearDynamics heave() {
    return {1, {mass + added}, {damping}, {stiffness}};
}

} // namespace

TEST_CASE("a heaving cylinder: X = F / (C33 - w^2 (m + A) + i w b)") {
    for (double w : {0.05, 0.3, 0.59, 1.1, 2.5}) {
        const Complex f(stiffness * 0.8, -1e4 * w);
        const Complex x = frequency_response(heave(), w, {{f}})[0];
        const Complex expected = f / Complex(stiffness - w * w * (mass + added), w * damping);
        CAPTURE(w);
        CHECK(std::abs(x - expected) < 1e-12 * std::abs(expected));
    }
}

TEST_CASE("a heaving cylinder: resonance at sqrt(C33 / (m + A)), where X = F / (i w b)") {
    const double wn = std::sqrt(stiffness / (mass + added));
    const Complex x = frequency_response(heave(), wn, {{Complex(1e5, 0)}})[0];
    CHECK(x.real() == doctest::Approx(0).epsilon(1e-12).scale(std::abs(x)));
    CHECK(x.imag() == doctest::Approx(-1e5 / (wn * damping)).epsilon(1e-12));
    // |X| falls on either side of the (lightly damped) resonance: the peak is within
    // 1e-3 of wn on a fine grid (the damped peak is at wn sqrt(1 - 2 zeta^2)).
    double best = 0, at = 0;
    for (double w = 0.5 * wn; w < 1.5 * wn; w += 1e-4 * wn) {
        const double m = std::abs(frequency_response(heave(), w, {{Complex(1, 0)}})[0]);
        if (m > best) best = m, at = w;
    }
    const double zeta = damping / (2 * std::sqrt(stiffness * (mass + added)));
    CHECK(at == doctest::Approx(wn * std::sqrt(1 - 2 * zeta * zeta)).epsilon(2e-4));
}

TEST_CASE("a free-floating body follows long waves: heave RAO -> 1 as w -> 0") {
    // The Froude-Krylov heave force of a long wave is C33 eta (the undisturbed
    // pressure on the bottom), less the inertia w^2 (m + A) eta of the fluid it moves.
    for (double w : {1e-2, 1e-3, 1e-4}) {
        const Complex f(stiffness - w * w * (mass + added), 0);
        const Complex x = frequency_response(heave(), w, {{f}})[0];
        CAPTURE(w);
        CHECK(std::abs(x - 1.0) < 1.01 * w * damping / stiffness);
    }
}

TEST_CASE("two DOFs: the solve equals Cramer's rule; A(w), B(w) add to M and C") {
    const LinearDynamics m{2, {3, 0.4, 0.4, 2}, {0.1, 0.02, 0.02, 0.3}, {10, -2, -2, 6}};
    const std::vector<Complex> f{{1, 0.5}, {-0.3, 2}};
    for (double w : {0.2, 1.7, 2.4}) {
        const auto z = [&](int i, int j) {
            return Complex(-w * w * m.M[2 * i + j] + m.K[2 * i + j], w * m.C[2 * i + j]);
        };
        const Complex det = z(0, 0) * z(1, 1) - z(0, 1) * z(1, 0);
        const Complex x0 = (f[0] * z(1, 1) - z(0, 1) * f[1]) / det;
        const Complex x1 = (z(0, 0) * f[1] - z(1, 0) * f[0]) / det;
        const std::vector<Complex> x = frequency_response(m, w, {f});
        CAPTURE(w);
        CHECK(std::abs(x[0] - x0) < 1e-12 * std::abs(x0));
        CHECK(std::abs(x[1] - x1) < 1e-12 * std::abs(x1));
        // The same model split into a constant part and a frequency's terms.
        const LinearDynamics base{2, {2, 0.4, 0.4, 2}, {0.1, 0, 0, 0.3}, m.K};
        const std::vector<Complex> y =
            frequency_response(base, w, {f, {1, 0, 0, 0}, {0, 0.02, 0.02, 0}});
        CHECK(std::abs(y[0] - x0) < 1e-12 * std::abs(x0));
        CHECK(std::abs(y[1] - x1) < 1e-12 * std::abs(x1));
    }
    CHECK_THROWS_AS(frequency_response(m, 1, {{f[0]}}), std::invalid_argument);
    CHECK_THROWS_AS(frequency_response({1, {0}, {0}, {0}}, 0, {{1}}), std::invalid_argument);
}

TEST_CASE("the variance of an oscillator in white noise: pi S0 / (2 k c)") {
    // int_0^inf |1 / (k - m w^2 + i c w)|^2 dw = pi / (2 k c).
    const double m = 2, c = 0.05, k = 8, s0 = 0.3;
    const LinearDynamics osc{1, {m}, {c}, {k}};
    std::vector<double> omega, spectrum;
    std::vector<std::vector<Complex>> rao;
    for (double w = 1e-3; w < 200; w += 1e-3) {
        omega.push_back(w);
        spectrum.push_back(s0);
        rao.push_back(frequency_response(osc, w, {{Complex(1, 0)}}));
    }
    const auto r = yamsc::runtime::sea_response(omega, rao, spectrum);
    // The grid stops at 200 rad/s (tail 1 / (3 m^2 w^3) of it: 2e-8) and starts at
    // 1e-3 (1e-3 / k^2): both far below the trapezoid's 1e-6 on the peak's width.
    CHECK(r.variance[0] == doctest::Approx(M_PI * s0 / (2 * k * c)).epsilon(1e-5));
    CHECK(r.standard_deviation[0] == doctest::Approx(std::sqrt(r.variance[0])));
    CHECK(r.spectra[10][0] == doctest::Approx(std::norm(rao[10][0]) * s0));
    // An output y = 2 q1 - q1 = q1: the DOF's response.
    const auto y = yamsc::runtime::output_responses({{Complex(1, 2)}}, {2, -1}, 2);
    CHECK(y[0][0] == Complex(2, 4));
    CHECK(y[0][1] == Complex(-1, -2));
}
