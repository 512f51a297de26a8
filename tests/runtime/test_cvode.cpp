// CVODE: accuracy against exact solutions, energy conservation, the exact
// versus difference-quotient Jacobian, and failures turned into exceptions.
#include "runtime/test_models.hpp"

#include "yamsc/cvode.hpp"

#include <cvode/cvode.h>
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace yamsc::runtime;

namespace {

constexpr double pi = 3.14159265358979323846;

CvodeOptions tight() {
    CvodeOptions o;
    o.rtol = 1e-12;
    o.atol = 1e-14;
    return o;
}

double oscillator_max_error(const ModelView& view, const test_oscillator::Params& p,
                            const CvodeOptions& options, CvodeStats* stats = nullptr) {
    double worst = 0.0;
    int samples = 0;
    const CvodeStats s = simulate_cvode(
        view, {0.1, -0.5}, std::vector<double>{1.0}, 5.0, 0.05,
        [&](double t, const double* x) {
            const auto exact = reference::oscillator(p, 1.0, 0.1, -0.5, t);
            worst = std::max({worst, std::abs(x[0] - exact.x), std::abs(x[1] - exact.v)});
            ++samples;
            return true;
        },
        options);
    CHECK(samples == 101);
    if (stats) *stats = s;
    return worst;
}

// Complete elliptic integral of the first kind by the arithmetic-geometric mean.
double elliptic_k(double modulus) {
    double a = 1.0, b = std::sqrt(1.0 - modulus * modulus);
    for (int i = 0; i < 30; ++i) {
        const double next_a = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = next_a;
    }
    return pi / (2.0 * a);
}

} // namespace

TEST_CASE("CVODE at tight tolerance matches the exact oscillator solution") {
    const test_oscillator::Params p;
    const ModelView view = from_generated<test_oscillator::Model>(p);
    CvodeStats stats;
    const double error = oscillator_max_error(view, p, tight(), &stats);
    MESSAGE("max error ", error, " in ", stats.steps, " steps, ", stats.jacobian_evals,
            " Jacobian evaluations");
    CHECK(error < 1e-8);
    CHECK(stats.exact_jacobian);
    CHECK(stats.jacobian_evals > 0);
}

TEST_CASE("CVODE without the exact Jacobian falls back to difference quotients") {
    const test_oscillator::Params p;
    ModelView view = from_generated<test_oscillator::Model>(p);
    view.rhs_jacobian = nullptr;
    CvodeStats stats;
    const double error = oscillator_max_error(view, p, tight(), &stats);
    MESSAGE("max error without exact Jacobian ", error, " in ", stats.steps, " steps");
    CHECK(error < 1e-8);
    CHECK_FALSE(stats.exact_jacobian);
}

TEST_CASE("looser tolerances give larger errors") {
    const test_oscillator::Params p;
    const ModelView view = from_generated<test_oscillator::Model>(p);
    CvodeOptions loose;
    loose.rtol = 1e-4;
    loose.atol = 1e-6;
    const double error = oscillator_max_error(view, p, loose);
    MESSAGE("max error at rtol 1e-4: ", error);
    CHECK(error > 1e-7);
    CHECK(error < 1e-2);
}

TEST_CASE("CVODE conserves the pendulum's energy and period at large amplitude") {
    const test_pendulum::Params p;
    const ModelView view = from_generated<test_pendulum::Model>(p);
    const double q0 = 2.5; // rad: far from the linear regime
    const double period = 4.0 * std::sqrt(p.l / p.g) * elliptic_k(std::sin(q0 / 2.0));
    const double energy0 = p.m * p.g * p.l * (1.0 - std::cos(q0));

    CvodeOptions options;
    options.rtol = 1e-12;
    options.atol = 1e-14;
    double drift = 0.0;
    std::vector<double> last(2);
    // Ten periods, sampled so that the last output is exactly at 10 T.
    simulate_cvode(
        view, {q0, 0.0}, std::vector<double>{}, 10.0 * period, period / 50.0,
        [&](double, const double* x) {
            double energy;
            view.outputs(0.0, x, x + 1, nullptr, &energy);
            drift = std::max(drift, std::abs(energy - energy0) / energy0);
            last.assign(x, x + 2);
            return true;
        },
        options);
    MESSAGE("relative energy drift ", drift, "; after 10 periods q - q0 = ", last[0] - q0,
            ", q' = ", last[1]);
    CHECK(drift < 1e-7);
    CHECK(last[0] == doctest::Approx(q0).epsilon(1e-6));
    CHECK(std::abs(last[1]) < 1e-5);
}

TEST_CASE("CVODE follows a time-varying input") {
    test_oscillator::Params p;
    p.m = 1.0;
    p.c = 0.0;
    p.k = 1.0;
    const ModelView view = from_generated<test_oscillator::Model>(p);
    double worst = 0.0;
    simulate_cvode(
        view, {0.1, 0.0}, [](double t, double* u) { u[0] = std::cos(2.0 * t); }, 6.0, 0.1,
        [&](double t, const double* x) {
            const double exact = (0.1 + 1.0 / 3.0) * std::cos(t) - std::cos(2.0 * t) / 3.0;
            worst = std::max(worst, std::abs(x[0] - exact));
            return true;
        },
        tight());
    CHECK(worst < 1e-8);
}

TEST_CASE("CVODE failures are exceptions with CVODE's reason") {
    const test_oscillator::Params p;
    const ModelView view = from_generated<test_oscillator::Model>(p);
    const StateObserver none;

    SUBCASE("too many steps") {
        CvodeOptions starved = tight();
        starved.max_steps_per_output = 3;
        try {
            simulate_cvode(view, {0.1, 0.0}, std::vector<double>{0.0}, 5.0, 1.0, none, starved);
            FAIL("expected a CvodeError");
        } catch (const CvodeError& e) {
            CHECK(e.flag() == CV_TOO_MUCH_WORK);
            CHECK(std::string(e.what()).find("CV_TOO_MUCH_WORK") != std::string::npos);
            MESSAGE(std::string(e.what()));
        }
    }
    SUBCASE("a right-hand side that is never finite") {
        ModelView broken = view;
        broken.rhs = [](double, const double*, const double*, double* xdot) {
            xdot[0] = NAN;
            xdot[1] = 0.0;
        };
        CHECK_THROWS_AS(
            simulate_cvode(broken, {0.1, 0.0}, std::vector<double>{0.0}, 1.0, 0.1, none),
            CvodeError);
    }
    SUBCASE("an exception from the model passes through unchanged") {
        ModelView throwing = view;
        throwing.rhs = [](double t, const double*, const double*, double*) {
            if (t > 0.5) throw std::domain_error("table lookup out of range");
        };
        CHECK_THROWS_WITH_AS(
            simulate_cvode(throwing, {0.1, 0.0}, std::vector<double>{0.0}, 1.0, 0.1, none),
            "table lookup out of range", std::domain_error);
    }
    SUBCASE("an exception from the observer passes through unchanged") {
        CHECK_THROWS_WITH_AS(simulate_cvode(view, {0.1, 0.0}, std::vector<double>{0.0}, 1.0, 0.1,
                                            [](double t, const double*) -> bool {
                                                if (t > 0.5) throw std::logic_error("stop");
                                                return true;
                                            }),
                             "stop", std::logic_error);
    }
    SUBCASE("bad options") {
        CvodeOptions bad;
        bad.rtol = 0.0;
        CHECK_THROWS_AS(
            simulate_cvode(view, {0.1, 0.0}, std::vector<double>{0.0}, 1.0, 0.1, none, bad),
            std::invalid_argument);
        CHECK_THROWS_AS(simulate_cvode(view, {0.1}, std::vector<double>{0.0}, 1.0, 0.1, none),
                        std::invalid_argument);
        CHECK_THROWS_AS(simulate_cvode(view, {0.1, 0.0}, std::vector<double>{0.0}, 1.0, -1.0, none),
                        std::invalid_argument);
    }
}

TEST_CASE("CVODE takes few steps on a stiff model where RK4 would need thousands") {
    // A 1e8 N/m coupling spring (1e4 rad/s) next to 6 rad/s: RK4 needs
    // dt < 2.8e-4 s for stability, BDF with the exact Jacobian does not care.
    test_two_masses::Params p;
    p.k2 = 1e8;
    p.beta = 1e-4; // damps the stiff mode (zeta 0.5), as structural damping does
    const ModelView view = from_generated<test_two_masses::Model>(p);
    CvodeOptions options;
    options.rtol = 1e-6;
    options.atol = 1e-9;
    const CvodeStats stats = simulate_cvode(view, {0.1, 0.1, 0.0, 0.0}, std::vector<double>{}, 10.0,
                                            0.1, StateObserver{}, options);
    MESSAGE("stiff run: ", stats.steps, " steps, ", stats.rhs_evals, " rhs evaluations, ",
            stats.jacobian_evals, " Jacobians");
    CHECK(stats.steps < 5000);
}
