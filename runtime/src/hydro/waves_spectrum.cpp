// SeaState's spectrum, time grid and random amplitudes (OpenFAST's Waves.f90:
// WavePkShpDefault, JONSWAP, VariousWaves_Init's grid, Get_1Spsd_and_WaveElevC0).
#include "yamsc/hydro/ranlux.hpp"
#include "yamsc/hydro/waves.hpp"
#include "yamsc/wind/turbulence.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace yamsc::runtime::hydro {

namespace {
constexpr double pi = 3.14159265358979323846;

// SeaState's BoxMuller: U1 redrawn while zero, then U2; the modulus sqrt(-2 ln U1)
// (or its mean sqrt(2) with constant amplitudes), the phase 2 pi U2 or the one given.
std::complex<double> box_muller(Ranlux& rng, bool normal, const std::optional<double>& phase) {
    double u1 = 0;
    while (u1 == 0) u1 = rng.next();
    const double u2 = rng.next();
    const double c1 = normal ? std::sqrt(-2 * std::log(u1)) : std::sqrt(2.0);
    return std::polar(c1, phase ? *phase : 2 * pi * u2);
}

// SeaState seeds RANLUX with |WaveSeed(1)| alone; the compiler's intrinsic generator
// it uses otherwise cannot be reproduced, so both seeds seed RANLUX instead.
std::int64_t ranlux_seed(const WaveSettings& s) {
    const std::int64_t s1 = std::llabs(static_cast<long long>(s.seed1));
    if (s.ranlux) return s1 % 2147483648LL;
    const std::int64_t s2 = s.seed2 ? std::llabs(static_cast<long long>(*s.seed2)) : 0;
    return (s1 * 69069 + s2 * 1013904223LL + 1) % 2147483647LL;
}
} // namespace

double default_peak_shape(double hs, double tp) {
    if (hs <= 0) return 1;
    const double r = tp / std::sqrt(hs);
    if (r <= 3.6) return 5;
    if (r >= 5) return 1;
    return std::exp(5.75 - 1.15 * r);
}

double jonswap(double omega, double hs, double tp, double gamma) {
    if (omega <= 0) return 0;
    const double f = omega / (2 * pi), fp = 1 / tp;
    const double r4 = std::pow(fp / f, 4);
    const double sigma = f <= fp ? 0.07 : 0.09;
    const double alpha = std::exp(-0.5 * std::pow((f * tp - 1) / sigma, 2));
    const double c = 1 - 0.287 * std::log(gamma);
    return c * (0.3125 * hs * hs * r4 / f) * std::exp(-1.25 * r4) * std::pow(gamma, alpha) /
           (2 * pi);
}

double wave_number(double omega, double gravity, double depth) {
    if (omega <= 0) return 0;
    const double deep = omega * omega / gravity;
    if (deep * depth > 40) return deep; // tanh(k h) = 1 to double precision
    // Newton on f(k) = g k tanh(k h) - omega^2, convex in k: from the larger of the deep
    // and shallow estimates it decreases monotonically to the root.
    double k = std::max(deep, omega / std::sqrt(gravity * depth));
    for (int it = 0; it < 100; ++it) {
        const double t = std::tanh(k * depth);
        const double f = gravity * k * t - omega * omega;
        const double df = gravity * (t + k * depth * (1 - t * t));
        const double dk = f / df;
        k -= dk;
        if (std::abs(dk) <= 1e-15 * k) break;
    }
    return k;
}

int wave_time_steps(double t_max, double dt) {
    if (!(dt > 0) || !(t_max > 0))
        throw std::invalid_argument("waves: WaveTMax and WaveDT must be > 0");
    if (t_max / dt > 1e8) throw std::invalid_argument("waves: WaveTMax / WaveDT is above 1e8");
    int n = static_cast<int>(std::ceil(t_max / dt));
    if (n % 2 == 1) ++n;
    // NWTC's PSF(n, 9), the smallest product of primes up to 23, as TurbSim's.
    return 2 * small_prime_product(std::max(n / 2, 1));
}

std::vector<std::complex<double>> sea_state_amplitudes(const WaveSettings& s, int n) {
    const int n2 = n / 2;
    const double d_omega = 2 * pi / (n * s.dt);
    std::vector<std::complex<double>> a(static_cast<std::size_t>(n2) + 1);
    if (s.kind == WaveKind::still) return a;

    // White Gaussian noise of unit variance: drawn for m = 0 and 2 .. n/2 - 1, in this
    // order (SeaState leaves out m = 1, not m = 0, and the Nyquist component).
    Ranlux rng(3, ranlux_seed(s));
    std::vector<std::complex<double>> w(a.size());
    const std::optional<double> phase = s.kind == WaveKind::regular ? s.phase : std::nullopt;
    for (int m = 0; m < n2; ++m)
        if (m != 1) w[static_cast<std::size_t>(m)] = box_muller(rng, s.normal_amplitudes, phase);

    if (s.kind == WaveKind::regular) {
        // One component, at the grid frequency nearest 2 pi / T, of amplitude H / 2 and
        // the phase drawn for it (or the one given).
        const long m = std::lround(2 * pi / (d_omega * s.period));
        if (!(s.period > 0) || m <= 1 || m >= n2)
            throw std::invalid_argument(
                "waves: the regular wave's period must lie between 2 WaveDT and WaveTMax / 2 "
                "(SeaState gives still water otherwise)");
        const auto k = static_cast<std::size_t>(m);
        a[k] = std::polar(s.height / 2, std::arg(w[k]));
        return a;
    }
    if (!(s.period > 0)) throw std::invalid_argument("waves: the peak period must be > 0");
    const double gamma = s.peak_shape ? *s.peak_shape : default_peak_shape(s.height, s.period);
    if (!(gamma >= 1 && gamma <= 7))
        throw std::invalid_argument("waves: the peak shape must be 1 to 7 (SeaState's range)");
    for (int m = 0; m <= n2; ++m) {
        const double omega = m * d_omega;
        if (omega < s.low_cutoff || omega > s.high_cutoff) continue;
        const double sdd = jonswap(omega, s.height, s.period, gamma);
        a[static_cast<std::size_t>(m)] = w[static_cast<std::size_t>(m)] * std::sqrt(sdd * d_omega);
    }
    return a;
}

} // namespace yamsc::runtime::hydro
