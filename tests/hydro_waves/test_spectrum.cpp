// SeaState's spectrum, dispersion relation and time grid against closed forms.
#include <yamsc/hydro/waves.hpp>

#include <doctest/doctest.h>

#include <cmath>

using namespace yamsc::runtime::hydro;

namespace {
constexpr double pi = 3.14159265358979323846;

// The IEC 61400-3 JONSWAP spectrum in angular frequency, written independently of
// the one in hertz that SeaState evaluates.
double iec_jonswap(double w, double hs, double tp, double gamma) {
    const double wp = 2 * pi / tp;
    const double sigma = w <= wp ? 0.07 : 0.09;
    return (1 - 0.287 * std::log(gamma)) * 5.0 / 16.0 * hs * hs * std::pow(wp, 4) *
           std::pow(w, -5) * std::exp(-1.25 * std::pow(wp / w, 4)) *
           std::pow(gamma, std::exp(-std::pow(w - wp, 2) / (2 * sigma * sigma * wp * wp)));
}

double m0(double hs, double tp, double gamma, double dw, double w_max) {
    double sum = 0;
    for (double w = dw; w < w_max; w += dw) sum += jonswap(w, hs, tp, gamma) * dw;
    return sum;
}
} // namespace

TEST_CASE("JONSWAP: SeaState's form in hertz is the IEC spectrum in rad/s") {
    for (double gamma : {1.0, 2.0, 3.3, 7.0})
        for (double w : {0.2, 0.45, 0.6, 0.628, 0.7, 1.0, 2.5}) {
            CAPTURE(gamma);
            CAPTURE(w);
            CHECK(jonswap(w, 6, 10, gamma) ==
                  doctest::Approx(iec_jonswap(w, 6, 10, gamma)).epsilon(1e-13));
        }
    CHECK(jonswap(0, 6, 10, 3.3) == 0);
}

TEST_CASE("JONSWAP: Pierson-Moskowitz (gamma 1) has m0 = Hs^2/16 exactly") {
    // A fine Riemann sum to 40 rad/s; the tail beyond holds Hs^2/16 (5/4) wp^4/(4 w^4) ~ 1e-7.
    const double hs = 6, tp = 10;
    CHECK(m0(hs, tp, 1, 1e-4, 40) == doctest::Approx(hs * hs / 16).epsilon(2e-6));
    // On SeaState's grid for WaveTMax = 3600 s (dw = 1.7e-3 rad/s) the sum is as good.
    CHECK(m0(hs, tp, 1, 2 * pi / 3600, 40) == doctest::Approx(hs * hs / 16).epsilon(2e-6));
}

TEST_CASE(
    "JONSWAP: the normalization 1 - 0.287 ln(gamma) holds m0 to 0.5 % (gamma 3.3), 2 % (gamma 7)") {
    // The factor is an approximation (IEC 61400-3): measured deviation of m0 from Hs^2/16.
    const double hs = 6, tp = 10;
    const double r33 = m0(hs, tp, 3.3, 1e-4, 40) / (hs * hs / 16) - 1;
    const double r7 = m0(hs, tp, 7, 1e-4, 40) / (hs * hs / 16) - 1;
    MESSAGE("m0 / (Hs^2/16) - 1: gamma 3.3 " << r33 << ", gamma 7 " << r7);
    CHECK(std::abs(r33) < 0.005); // measured 0.24 %
    CHECK(std::abs(r7) < 0.02);   // measured -1.75 %
}

TEST_CASE("The DEFAULT peak shape: IEC's from Tp / sqrt(Hs)") {
    CHECK(default_peak_shape(6, 10) ==
          doctest::Approx(std::exp(5.75 - 1.15 * 10 / std::sqrt(6.0))));
    CHECK(default_peak_shape(4, 7) == 5);   // 3.5 <= 3.6
    CHECK(default_peak_shape(1, 5.5) == 1); // 5.5 >= 5
    CHECK(default_peak_shape(0, 10) == 1);
}

TEST_CASE("Dispersion: omega^2 = g k tanh(k h), deep and finite depth") {
    const double g = 9.80665;
    // Deep water: k = omega^2 / g (k h > 40: tanh(k h) = 1 in double precision).
    for (double w : {0.3, 0.6, 1.2, 3.0})
        CHECK(wave_number(w, g, 5000) == doctest::Approx(w * w / g).epsilon(1e-14));
    // Finite depth: the k that gives omega through the closed form is found back.
    for (double h : {5.0, 20.0, 50.0})
        for (double k : {0.002, 0.01, 0.05, 0.2, 1.0}) {
            const double w = std::sqrt(g * k * std::tanh(k * h));
            CAPTURE(h);
            CAPTURE(k);
            CHECK(wave_number(w, g, h) == doctest::Approx(k).epsilon(1e-12));
        }
    // Shallow water: k -> omega / sqrt(g h).
    CHECK(wave_number(1e-4, g, 10) == doctest::Approx(1e-4 / std::sqrt(g * 10)).epsilon(1e-8));
    CHECK(wave_number(0, g, 10) == 0);
}

TEST_CASE("SeaState's time grid: even, twice a product of primes up to 23, >= WaveTMax/WaveDT") {
    CHECK(wave_time_steps(600, 0.25) == 2400);
    CHECK(wave_time_steps(3630, 0.25) == 14520); // 7260 = 2^2 3 5 11^2
    CHECK(wave_time_steps(14.5, 0.25) == 60);    // 58 / 2 = 29 is prime: 30
    CHECK(wave_time_steps(14.25, 0.25) == 60);   // 57 is odd: 58, then 60
    CHECK(wave_time_steps(0.1, 0.25) == 2);
}
