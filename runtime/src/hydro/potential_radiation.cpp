#include <yamsc/hydro/potential_flow.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::runtime::hydro {
namespace {

constexpr double pi = 3.14159265358979323846;

/// Whether n's prime factors are all among the first `primes` primes (NWTC's PSF).
bool small_factors(int n, int primes) {
    static const int prime[9] = {2, 3, 5, 7, 11, 13, 17, 19, 23};
    for (int k = 0; k < std::min(primes, 9); ++k)
        while (n % prime[k] == 0) n /= prime[k];
    return n == 1;
}

/// B at w: linear between the table's frequencies, held beyond them (InterpStp).
Mat6 damping_at(const std::vector<double>& omega, const std::vector<Mat6>& b, double w) {
    if (w <= omega.front()) return b.front();
    if (w >= omega.back()) return b.back();
    const auto hi = std::upper_bound(omega.begin(), omega.end(), w);
    const std::size_t k = static_cast<std::size_t>(hi - omega.begin());
    const double s = (w - omega[k - 1]) / (omega[k] - omega[k - 1]);
    Mat6 out;
    for (std::size_t i = 0; i < 36; ++i) out[i] = (1 - s) * b[k - 1][i] + s * b[k][i];
    return out;
}

} // namespace

std::vector<Mat6> radiation_kernel(const std::vector<double>& omega,
                                   const std::vector<Mat6>& damping, double dt, double t_max) {
    if (!(dt > 0) || !(t_max >= 0))
        throw std::invalid_argument("radiation kernel: RdtnDT must be positive");
    if (omega.empty() || omega.size() != damping.size())
        throw std::invalid_argument("radiation kernel: no damping table");
    const double omega_max = pi / dt;
    for (std::size_t k = 0; k + 1 < omega.size(); ++k)
        if (omega[k] > omega_max)
            throw std::invalid_argument("radiation kernel: RdtnDT must be smaller than " +
                                        std::to_string(pi / omega[k]) +
                                        " s (pi over the highest WAMIT frequency)");
    // Conv_Radiation's size: odd, then (N - 1) / 2 raised to a product of small primes.
    const double steps = std::ceil(t_max / dt);
    if (steps > 1e7) throw std::invalid_argument("radiation kernel: RdtnTMax / RdtnDT over 1e7");
    int n = static_cast<int>(steps);
    if (n % 2 == 0) ++n;
    int half = std::max((n - 1) / 2, 1);
    while (!small_factors(half, 9)) ++half;
    n = 2 * half + 1;
    const double d_omega = pi / ((n - 1) * dt);
    std::vector<Mat6> b(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k)
        b[static_cast<std::size_t>(k)] = damping_at(omega, damping, k * d_omega);
    std::vector<Mat6> kernel(static_cast<std::size_t>(n));
    // The cosine transform as a trapezoid sum; cos(w_k t_j) = cos(pi k j / (N - 1)).
    std::vector<double> c(static_cast<std::size_t>(2 * (n - 1)));
    for (std::size_t m = 0; m < c.size(); ++m)
        c[m] = std::cos(pi * static_cast<double>(m) / (n - 1));
    // Only the entries some B has (a spar's are about 10 of 36).
    std::vector<std::size_t> entries;
    for (std::size_t i = 0; i < 36; ++i)
        if (std::any_of(damping.begin(), damping.end(), [i](const Mat6& m) { return m[i] != 0; }))
            entries.push_back(i);
    for (int j = 0; j < n; ++j) {
        Mat6& K = kernel[static_cast<std::size_t>(j)];
        K.fill(0);
        for (int k = 0; k < n; ++k) {
            const double w =
                (k == 0 || k == n - 1 ? 0.5 : 1.0) *
                c[static_cast<std::size_t>((static_cast<long>(k) * j) % (2 * (n - 1)))];
            const Mat6& bk = b[static_cast<std::size_t>(k)];
            for (std::size_t i : entries) K[i] += w * bk[i];
        }
        for (std::size_t i : entries) K[i] *= 2 / pi * d_omega;
    }
    return kernel;
}

} // namespace yamsc::runtime::hydro
