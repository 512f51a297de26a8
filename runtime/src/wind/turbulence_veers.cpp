// Veers' method as TurbSim's CalcFourierCoeffs_IEC, Coh2H, H2Coeffs and
// Coeffs2TimeSeries apply it, then TurbSim's TimeSeriesScaling_IEC and the mean
// profile (AddMeanAndRotate without flow angles).
//
// The random phases are yamsc's, not TurbSim's: std::mt19937_64 seeded with the
// seed's 64-bit two's complement, each phase 2 pi (x >> 11) 2^-53 of one draw x, drawn
// in TurbSim's order (the point fastest, then the frequency k = 1 .. N/2, then the
// component u, v, w). The standard fixes mt19937_64's sequence, so a seed gives the
// same field on every platform; TurbSim's RanLux draws differ, so the same seed gives
// another realisation than TurbSim.
#include "turbulence_fft.hpp"
#include "yamsc/wind/turbulence.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <string>

namespace yamsc::runtime {

namespace {

struct Points {
    std::vector<double> y, z;
    int hub = 0;
};

// The grid row by row from the bottom (y fastest), then the hub if it is not on the
// grid: TurbSim's order, which is also the Cholesky factor's.
Points points_of(const TurbulenceSpec& s, const TurbulenceLayout& l) {
    Points p;
    for (int iz = 0; iz < s.nz; ++iz)
        for (int iy = 0; iy < s.ny; ++iy) {
            p.y.push_back(-0.5 * s.width + l.dy * iy);
            p.z.push_back(l.z_bottom + l.dz * iz);
        }
    if (l.hub_on_grid) {
        const int iz = static_cast<int>(1e-4 + (s.hub_height - l.z_bottom) / l.dz);
        p.hub = iz * s.ny + (s.ny - 1) / 2;
    } else {
        p.hub = static_cast<int>(p.y.size());
        p.y.push_back(0.0);
        p.z.push_back(s.hub_height);
    }
    return p;
}

/// The distinct distances between the points, and which one each pair has.
struct Separations {
    std::vector<double> distance;
    std::vector<std::size_t> pair_index; // row-major, np x np
    std::size_t np = 0;
    double closest = std::numeric_limits<double>::infinity(); // of two distinct points
    std::size_t index(int i, int j) const {
        return pair_index[static_cast<std::size_t>(i) * np + static_cast<std::size_t>(j)];
    }
};

Separations separations_of(const Points& pts) {
    Separations s;
    s.np = pts.y.size();
    const int np = static_cast<int>(s.np);
    std::map<double, std::size_t> seen;
    s.pair_index.resize(s.np * s.np);
    for (int i = 0; i < np; ++i)
        for (int j = 0; j < np; ++j) {
            const double r = std::hypot(pts.y[i] - pts.y[j], pts.z[i] - pts.z[j]);
            if (i != j) s.closest = std::min(s.closest, r);
            const auto [at, added] = seen.emplace(r, s.distance.size());
            if (added) s.distance.push_back(r);
            s.pair_index[static_cast<std::size_t>(i) * s.np + static_cast<std::size_t>(j)] =
                at->second;
        }
    return s;
}

double sigma_of(const double* x, int n) {
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        sum += x[i];
        sum2 += x[i] * x[i];
    }
    const double mean = sum / n;
    return std::sqrt(std::abs(sum2 / n - mean * mean));
}

} // namespace

TurbulenceField generate_turbulence(const TurbulenceSpec& s,
                                    const std::function<void(double)>& progress) {
    TurbulenceField field;
    field.iec = iec_parameters(s);
    field.layout = turbulence_layout(s);
    field.ny = s.ny;
    field.nz = s.nz;
    const IecParameters& iec = field.iec;
    const TurbulenceLayout& layout = field.layout;
    const Points pts = points_of(s, layout);
    const int np = static_cast<int>(pts.y.size());
    const int n = layout.fft_steps;
    const int nf = n / 2;
    const double df = 1.0 / (n * s.time_step);
    const std::size_t un = static_cast<std::size_t>(n);

    std::mt19937_64 rng(static_cast<std::uint64_t>(s.seed));
    const double two_pi = 2 * std::acos(-1.0);
    auto phase = [&] { return two_pi * static_cast<double>(rng() >> 11) * 0x1.0p-53; };

    // A regular grid has few distinct separations (one per grid offset), so the
    // coherence is computed once per separation and frequency, not once per pair.
    const Separations separations = separations_of(pts);
    const double closest = separations.closest;
    // Above some frequency every pair's coherence is below 1e-16 / np: the
    // coherence matrix is the identity to rounding, and so is its Cholesky factor
    // (each coefficient changes by less than 1e-16 of its size). Its LLT, the
    // generator's cost, is skipped there: most frequencies at low wind speeds.
    auto uncorrelated = [&](double f) {
        return np < 2 || iec_coherence(iec, f, closest) < 1e-16 / np;
    };

    // series[(c * np + i) * n + it]: the fluctuations, zero mean.
    std::vector<double> series(3 * static_cast<std::size_t>(np) * un);
    std::vector<std::complex<double>> coefficients(static_cast<std::size_t>(np) * un);
    std::vector<std::complex<double>> spectrum(un), time(un);
    std::vector<std::complex<double>> rotation(static_cast<std::size_t>(np));
    const Fft fft(n);
    Eigen::MatrixXd coherence(np, np);
    std::vector<double> coherence_of(separations.distance.size());
    const double work_total = 3.0 * nf;
    double last_report = -1;

    for (int c = 0; c < 3; ++c) {
        std::fill(coefficients.begin(), coefficients.end(), std::complex<double>());
        for (int k = 1; k <= nf; ++k) {
            const double f = k * df;
            const double amplitude = std::sqrt(kaimal_spectrum(iec, c, f) * df / 2);
            for (int j = 0; j < np; ++j)
                rotation[static_cast<std::size_t>(j)] = std::polar(1.0, phase());
            if (k == nf)
                continue; // the Nyquist term is set to zero (its phases drawn all the same)
            if (c == 0 && !uncorrelated(f)) {
                for (std::size_t d = 0; d < separations.distance.size(); ++d)
                    coherence_of[d] = iec_coherence(iec, f, separations.distance[d]);
                for (int j = 0; j < np; ++j)
                    for (int i = j; i < np; ++i)
                        coherence(i, j) = coherence_of[separations.index(i, j)];
                const Eigen::LLT<Eigen::MatrixXd, Eigen::Lower> llt(coherence);
                if (llt.info() != Eigen::Success)
                    throw std::runtime_error("turbulence: the u coherence matrix at " +
                                             std::to_string(f) + " Hz is not positive definite");
                const Eigen::MatrixXd& lower = llt.matrixLLT();
                for (int i = 0; i < np; ++i) {
                    std::complex<double> sum;
                    for (int j = 0; j <= i; ++j)
                        sum += lower(i, j) * rotation[static_cast<std::size_t>(j)];
                    coefficients[static_cast<std::size_t>(i) * un + static_cast<std::size_t>(k)] =
                        amplitude * sum;
                }
            } else {
                for (int i = 0; i < np; ++i)
                    coefficients[static_cast<std::size_t>(i) * un + static_cast<std::size_t>(k)] =
                        amplitude * rotation[static_cast<std::size_t>(i)];
            }
            const double done = (c * nf + k) / work_total;
            if (progress && done - last_report >= 0.01) {
                progress(done);
                last_report = done;
            }
        }
        // Two points per transform: each spectrum is Hermitian, so its series is
        // real, and the series of X + iY are x + iy.
        for (int i = 0; i < np; i += 2) {
            const bool pair = i + 1 < np;
            const std::complex<double>* x = coefficients.data() + static_cast<std::size_t>(i) * un;
            const std::complex<double>* y = pair ? x + un : nullptr;
            const std::complex<double> unit(0, 1);
            spectrum[0] = 0;
            for (int k = 1; k < nf; ++k) {
                const std::complex<double> yk = pair ? y[k] : std::complex<double>();
                spectrum[static_cast<std::size_t>(k)] = x[k] + unit * yk;
                spectrum[un - static_cast<std::size_t>(k)] = std::conj(x[k]) + unit * std::conj(yk);
            }
            spectrum[static_cast<std::size_t>(nf)] = 0;
            fft.inverse(spectrum.data(), time.data());
            double* out = series.data() + (static_cast<std::size_t>(c) * np + i) * un;
            for (std::size_t it = 0; it < un; ++it) out[it] = time[it].real();
            if (pair)
                for (std::size_t it = 0; it < un; ++it) out[un + it] = time[it].imag();
        }
    }

    // TurbSim's ScaleIEC, over all N steps.
    if (s.scaling != SigmaScaling::none) {
        for (int c = 0; c < 3; ++c) {
            double* hub = series.data() + (static_cast<std::size_t>(c) * np + pts.hub) * un;
            const double hub_factor = iec.sigma[c] / sigma_of(hub, n);
            for (int i = 0; i < np; ++i) {
                double* x = series.data() + (static_cast<std::size_t>(c) * np + i) * un;
                const double factor = s.scaling == SigmaScaling::hub || c > 0 || i == pts.hub
                                          ? hub_factor
                                          : iec.sigma[c] / sigma_of(x, n);
                for (std::size_t it = 0; it < un; ++it) x[it] *= factor;
            }
        }
    }

    field.hub.resize(3 * un);
    for (int c = 0; c < 3; ++c)
        for (std::size_t it = 0; it < un; ++it)
            field.hub[it * 3 + static_cast<std::size_t>(c)] =
                series[(static_cast<std::size_t>(c) * np + pts.hub) * un + it];

    const int ng = s.ny * s.nz;
    const std::size_t nt = static_cast<std::size_t>(layout.steps_written);
    field.grid.resize(nt * static_cast<std::size_t>(ng) * 3);
    for (int i = 0; i < ng; ++i) {
        const double u_mean = mean_speed(s, pts.z[static_cast<std::size_t>(i)]);
        for (int c = 0; c < 3; ++c) {
            const double* x = series.data() + (static_cast<std::size_t>(c) * np + i) * un;
            const double mean = c == 0 ? u_mean : 0.0;
            for (std::size_t it = 0; it < nt; ++it)
                field.grid[(it * static_cast<std::size_t>(ng) + static_cast<std::size_t>(i)) * 3 +
                           static_cast<std::size_t>(c)] = static_cast<float>(mean + x[it]);
        }
    }
    if (progress) progress(1.0);
    return field;
}

} // namespace yamsc::runtime
