// The IEC 61400-1 Ed. 3 parameters, spectra, coherence, mean profile and layout of
// a TurbSim IECKAI field (TS_FileIO.f90 CalcIECScalingParams, VelocitySpectra.f90
// Spec_IECKAI, TSsubs.f90 CreateGrid, Profiles.f90).
#include "yamsc/wind/turbulence.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::runtime {

namespace {

// TurbSim's tolerance on heights [m] (TurbSim_Types.f90 Tolerance).
constexpr double tolerance = 1e-4;

// ceil(x) that does not round x = 7200.000000001 (600 / 0.05 in binary) up.
int ceil_steps(double x) {
    return static_cast<int>(std::ceil(x * (1 - 1e-12)));
}

} // namespace

double mean_speed(const TurbulenceSpec& s, double z) {
    if (s.profile == MeanProfile::power_law)
        return s.ref_speed * std::pow(z / s.ref_height, s.power_law);
    return s.ref_speed * std::log(z / s.roughness) / std::log(s.ref_height / s.roughness);
}

IecParameters iec_parameters(const TurbulenceSpec& s) {
    if (!(s.hub_height > 0 && s.ref_height > 0 && s.ref_speed > 0))
        throw std::invalid_argument("turbulence: the hub height, RefHt and URef must be positive");
    IecParameters p;
    p.u_hub = mean_speed(s, s.hub_height);
    if (!(p.u_hub > 0 && std::isfinite(p.u_hub)))
        throw std::invalid_argument("turbulence: the mean speed at the hub must be positive");
    if (s.turbulence_class == TurbulenceClass::intensity) {
        if (s.model == TurbulenceModel::extreme)
            throw std::invalid_argument("turbulence: the extreme model needs a class A, B or C");
        p.sigma[0] = s.intensity * p.u_hub;
    } else {
        const double i_ref = s.turbulence_class == TurbulenceClass::A   ? 0.16
                             : s.turbulence_class == TurbulenceClass::B ? 0.14
                                                                        : 0.12;
        if (s.model == TurbulenceModel::normal) {
            p.sigma[0] = i_ref * (0.75 * p.u_hub + 5.6); // Ed. 3 (11)
        } else {
            if (s.turbine_class < 1 || s.turbine_class > 3)
                throw std::invalid_argument("turbulence: the turbine class must be 1, 2 or 3");
            const double v_ref = s.turbine_class == 1 ? 50.0 : s.turbine_class == 2 ? 42.5 : 37.5;
            const double v_ave = 0.2 * v_ref; // Ed. 3 (9)
            const double c = s.etm_c;
            p.sigma[0] = c * i_ref * (0.072 * (v_ave / c + 3) * (p.u_hub / c - 4) + 10); // (19)
        }
    }
    if (!(p.sigma[0] > 0))
        throw std::invalid_argument("turbulence: the standard deviation of u is not positive");
    p.sigma[1] = 0.8 * p.sigma[0];
    p.sigma[2] = 0.5 * p.sigma[0];
    p.lambda1 = 0.7 * std::min(s.hub_height, 60.0);
    p.length[0] = 8.1 * p.lambda1;
    p.length[1] = 2.7 * p.lambda1;
    p.length[2] = 0.66 * p.lambda1;
    p.coherence_length = 8.1 * p.lambda1;
    return p;
}

double kaimal_spectrum(const IecParameters& p, int c, double f) {
    const double l_over_u = p.length[c] / p.u_hub;
    return 4 * p.sigma[c] * p.sigma[c] * l_over_u / std::pow(1 + 6 * f * l_over_u, 5.0 / 3.0);
}

double iec_coherence(const IecParameters& p, double f, double r) {
    const double a = f * r / p.u_hub, b = 0.12 * r / p.coherence_length;
    return std::exp(-p.coherence_decay * std::sqrt(a * a + b * b));
}

int small_prime_product(int n) {
    for (int candidate = std::max(n, 1);; ++candidate) {
        int rest = candidate;
        for (int p : {2, 3, 5, 7, 11, 13, 17, 19, 23})
            while (rest % p == 0) rest /= p;
        if (rest == 1) return candidate;
    }
}

TurbulenceLayout turbulence_layout(const TurbulenceSpec& s) {
    if (s.ny < 2 || s.nz < 2 || !(s.width > 0) || !(s.height > 0))
        throw std::invalid_argument("turbulence: the grid needs 2 or more points each way and a "
                                    "positive size");
    if (!(s.time_step > 0) || !(s.analysis_time > 0) || !(s.usable_time > 0))
        throw std::invalid_argument("turbulence: the time step and times must be positive");
    TurbulenceLayout l;
    const double u_hub = mean_speed(s, s.hub_height);
    // TurbSim: NumSteps even and 2 x a product of small primes; non-periodic files add
    // the time the wind takes to cross the grid to the usable time.
    int steps = 0;
    if (s.periodic) {
        steps = ceil_steps(s.analysis_time / s.time_step);
    } else {
        l.steps_written = ceil_steps((s.usable_time + s.width / u_hub) / s.time_step);
        steps = std::max(ceil_steps(s.analysis_time / s.time_step), l.steps_written);
    }
    if (steps > 20000000) throw std::invalid_argument("turbulence: more than 2e7 time steps");
    l.fft_steps = 2 * small_prime_product((steps - 1) / 2 + 1);
    if (s.periodic) l.steps_written = l.fft_steps;
    l.dy = s.width / (s.ny - 1);
    l.dz = s.height / (s.nz - 1);
    // The grid's top at the hub + half the "rotor diameter", min(width, height).
    const double diameter = std::min(s.width, s.height);
    l.z_bottom = s.hub_height + 0.5 * diameter - l.dz * (s.nz - 1);
    if (!(l.z_bottom > tolerance))
        throw std::invalid_argument("turbulence: the grid reaches the ground (its bottom at " +
                                    std::to_string(l.z_bottom) + " m)");
    if (s.ny % 2 == 1) {
        const int iz = static_cast<int>(tolerance + (s.hub_height - l.z_bottom) / l.dz);
        l.hub_on_grid = std::abs(iz * l.dz + l.z_bottom - s.hub_height) <= tolerance;
    }
    return l;
}

} // namespace yamsc::runtime
