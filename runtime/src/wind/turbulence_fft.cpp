#include "turbulence_fft.hpp"

#include <cmath>
#include <stdexcept>

namespace yamsc::runtime {

Fft::Fft(int n) : n_(n) {
    if (n < 1) throw std::invalid_argument("FFT length must be positive");
    int rest = n;
    for (int p = 2; rest > 1;) {
        if (rest % p == 0) {
            factors_.push_back(p);
            rest /= p;
        } else {
            p = p * p > rest ? rest : p + 1;
        }
    }
    if (factors_.empty()) factors_.push_back(1);
    twiddle_.resize(static_cast<std::size_t>(n));
    const double pi = std::acos(-1.0);
    for (int m = 0; m < n; ++m)
        twiddle_[static_cast<std::size_t>(m)] = std::polar(1.0, 2 * pi * m / n);
}

// Transforms the n / (product of factors before `level`) values in[0], in[stride], ...
// into out[0 ..): the sub-transforms of each residue class, then one butterfly of
// radix p over them.
void Fft::work(std::complex<double>* out, const std::complex<double>* in, std::size_t stride,
               std::size_t level) const {
    const std::size_t p = static_cast<std::size_t>(factors_[level]);
    std::size_t m = 1;
    for (std::size_t l = level + 1; l < factors_.size(); ++l)
        m *= static_cast<std::size_t>(factors_[l]);
    if (m == 1) {
        for (std::size_t j = 0; j < p; ++j) out[j] = in[j * stride];
    } else {
        for (std::size_t q = 0; q < p; ++q)
            work(out + q * m, in + q * stride, stride * p, level + 1);
    }
    // out[q m + u] holds the q-th sub-transform's value u; the length here is p m and
    // its twiddle factors are exp(2 pi i t / (p m)) = twiddle_[t * stride].
    const std::size_t n = static_cast<std::size_t>(n_);
    std::vector<std::complex<double>> column(p);
    for (std::size_t u = 0; u < m; ++u) {
        for (std::size_t q = 0; q < p; ++q) column[q] = out[q * m + u];
        for (std::size_t r = 0; r < p; ++r) {
            const std::size_t k = u + r * m;
            std::complex<double> sum = column[0];
            for (std::size_t q = 1; q < p; ++q) sum += column[q] * twiddle_[(q * k * stride) % n];
            out[k] = sum;
        }
    }
}

void Fft::inverse(const std::complex<double>* in, std::complex<double>* out) const {
    if (n_ == 1) {
        out[0] = in[0];
        return;
    }
    work(out, in, 1, 0);
}

} // namespace yamsc::runtime
