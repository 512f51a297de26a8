// Eigen-analysis against closed forms: the two-mass chain's frequencies, Rayleigh
// damping ratios and mode shapes, rigid-body and real modes.
#include "runtime/test_models.hpp"

#include "yamsc/modal.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace yamsc::runtime;

namespace {

constexpr double two_pi = 6.28318530717958647692;

// Roots of det(K - w^2 M) = 0 for the two-mass chain, ascending.
std::vector<double> chain_omegas(const test_two_masses::Params& p) {
    const double a = p.m1 * p.m2;
    const double b = -(p.m1 * (p.k2 + p.k3) + p.m2 * (p.k1 + p.k2));
    const double c = (p.k1 + p.k2) * (p.k2 + p.k3) - p.k2 * p.k2;
    const double root = std::sqrt(b * b - 4.0 * a * c);
    return {std::sqrt((-b - root) / (2.0 * a)), std::sqrt((-b + root) / (2.0 * a))};
}

std::vector<Mode> modes_of(const test_two_masses::Params& p) {
    const ModelView view = from_generated<test_two_masses::Model>(p);
    return modal_analysis(state_matrix_from_view(view, {0, 0, 0, 0}, {}), 2);
}

} // namespace

TEST_CASE("undamped two-mass chain: frequencies and mode shapes in closed form") {
    const test_two_masses::Params p; // m 1, 3; k 40, 15, 25
    const auto omegas = chain_omegas(p);
    const auto modes = modes_of(p);
    REQUIRE(modes.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        const Mode& mode = modes[i];
        CHECK_FALSE(mode.rigid_body);
        CHECK_FALSE(mode.real);
        CHECK(mode.omega_n == doctest::Approx(omegas[i]).epsilon(1e-12));
        CHECK(mode.freq_hz == doctest::Approx(omegas[i] / two_pi).epsilon(1e-12));
        CHECK(std::abs(mode.damping_ratio) < 1e-12);
        CHECK(mode.eigenvalue.imag() > 0.0);
        // Shape: x2 / x1 = (k1 + k2 - m1 w^2) / k2, real, largest entry exactly 1.
        const double ratio = (p.k1 + p.k2 - p.m1 * omegas[i] * omegas[i]) / p.k2;
        REQUIRE(mode.shape.size() == 2);
        const auto measured = mode.shape[1] / mode.shape[0];
        CHECK(measured.real() == doctest::Approx(ratio).epsilon(1e-10));
        CHECK(std::abs(measured.imag()) < 1e-10);
        CHECK((mode.shape[0] == 1.0 || mode.shape[1] == 1.0));
        CHECK(std::max(std::abs(mode.shape[0]), std::abs(mode.shape[1])) == 1.0);
    }
    MESSAGE("f1 = ", modes[0].freq_hz, " Hz, f2 = ", modes[1].freq_hz, " Hz");
}

TEST_CASE("Rayleigh damping: zeta_i = alpha / (2 w_i) + beta w_i / 2") {
    test_two_masses::Params p;
    p.alpha = 0.3;
    p.beta = 0.002;
    const auto omegas = chain_omegas(p);
    const auto modes = modes_of(p);
    REQUIRE(modes.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        const double zeta = p.alpha / (2.0 * omegas[i]) + p.beta * omegas[i] / 2.0;
        CHECK(modes[i].omega_n == doctest::Approx(omegas[i]).epsilon(1e-12));
        CHECK(modes[i].damping_ratio == doctest::Approx(zeta).epsilon(1e-10));
        CHECK(modes[i].damped_freq_hz ==
              doctest::Approx(omegas[i] * std::sqrt(1.0 - zeta * zeta) / two_pi).epsilon(1e-10));
        MESSAGE("mode ", i, ": ", modes[i].freq_hz, " Hz, zeta ", modes[i].damping_ratio);
    }
}

TEST_CASE("a free pair of masses has one rigid-body mode first") {
    test_two_masses::Params p;
    p.k1 = 0.0;
    p.k3 = 0.0;
    const auto modes = modes_of(p);
    REQUIRE(modes.size() == 2);
    CHECK(modes[0].rigid_body);
    CHECK(modes[0].freq_hz == 0.0);
    CHECK(modes[0].shape[0].real() == doctest::Approx(1.0).epsilon(1e-9));
    CHECK(modes[0].shape[1].real() == doctest::Approx(1.0).epsilon(1e-9));
    CHECK_FALSE(modes[1].rigid_body);
    const double omega = std::sqrt(p.k2 * (p.m1 + p.m2) / (p.m1 * p.m2));
    CHECK(modes[1].omega_n == doctest::Approx(omega).epsilon(1e-12));
    const auto ratio = modes[1].shape[1] / modes[1].shape[0];
    CHECK(ratio.real() == doctest::Approx(-p.m1 / p.m2).epsilon(1e-10));
}

TEST_CASE("two unconnected free masses have two independent rigid-body modes") {
    test_two_masses::Params p;
    p.k1 = p.k2 = p.k3 = 0.0;
    const auto modes = modes_of(p);
    REQUIRE(modes.size() == 2);
    CHECK(modes[0].rigid_body);
    CHECK(modes[1].rigid_body);
}

TEST_CASE("a damped free mass: a rigid-body mode and a real decaying mode") {
    test_oscillator::Params p; // m = 2, c = 0.4
    p.k = 0.0;
    const ModelView view = from_generated<test_oscillator::Model>(p);
    const auto modes = modal_analysis(state_matrix_from_view(view, {0, 0}, {0}), 1);
    REQUIRE(modes.size() == 2);
    CHECK(modes[0].rigid_body);
    CHECK(modes[1].real);
    CHECK(modes[1].omega_n == doctest::Approx(p.c / p.m).epsilon(1e-12));
    CHECK(modes[1].damping_ratio == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("an overdamped oscillator has two real modes") {
    test_oscillator::Params p; // m = 2, k = 50: critical damping c = 20
    p.c = 30.0;
    const ModelView view = from_generated<test_oscillator::Model>(p);
    const auto modes = modal_analysis(state_matrix_from_view(view, {0, 0}, {0}), 1);
    REQUIRE(modes.size() == 2);
    const double root = std::sqrt(p.c * p.c - 4.0 * p.k * p.m);
    CHECK(modes[0].omega_n == doctest::Approx((p.c - root) / (2.0 * p.m)).epsilon(1e-12));
    CHECK(modes[1].omega_n == doctest::Approx((p.c + root) / (2.0 * p.m)).epsilon(1e-12));
    for (const Mode& m : modes) {
        CHECK(m.real);
        CHECK(m.damping_ratio == doctest::Approx(1.0).epsilon(1e-12));
        CHECK(m.damped_freq_hz == 0.0);
    }
}

TEST_CASE("an underdamped oscillator: one mode with the textbook frequency and damping") {
    const test_oscillator::Params p; // 5 rad/s, zeta = 0.4 / (2 sqrt(100)) = 0.02
    const ModelView view = from_generated<test_oscillator::Model>(p);
    const auto modes = modal_analysis(state_matrix_from_view(view, {0, 0}, {0}), 1);
    REQUIRE(modes.size() == 1);
    CHECK(modes[0].omega_n == doctest::Approx(5.0).epsilon(1e-13));
    CHECK(modes[0].damping_ratio == doctest::Approx(0.02).epsilon(1e-12));
}

TEST_CASE("state matrix: exact Jacobian at an operating point, difference fallback agrees") {
    const test_pendulum::Params p;
    ModelView view = from_generated<test_pendulum::Model>(p);
    const std::vector<double> x0{0.3, 0.7};
    const auto exact = state_matrix_from_view(view, x0, {});
    CHECK(exact[2] == doctest::Approx(-p.g / p.l * std::cos(0.3)).epsilon(1e-15));
    view.rhs_jacobian = nullptr;
    const auto approximate = state_matrix_from_view(view, x0, {});
    for (std::size_t i = 0; i < 4; ++i)
        CHECK(approximate[i] == doctest::Approx(exact[i]).epsilon(1e-8));

    // Hanging straight down: small oscillations at sqrt(g / l).
    const auto modes = modal_analysis(state_matrix_from_view(view, {0, 0}, {}), 1);
    REQUIRE(modes.size() == 1);
    CHECK(modes[0].freq_hz == doctest::Approx(std::sqrt(p.g / p.l) / two_pi).epsilon(1e-8));
}

TEST_CASE("modal analysis rejects malformed matrices") {
    CHECK_THROWS_AS(modal_analysis(std::vector<double>(9, 0.0), 2), std::invalid_argument);
    CHECK_THROWS_AS(modal_analysis({0, 1, NAN, 0}, 1), std::invalid_argument);
    CHECK_THROWS_AS(modal_analysis({}, 0), std::invalid_argument);
}
