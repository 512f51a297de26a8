#pragma once
// A mixed-radix FFT for the lengths TurbSim's generator uses (products of primes
// up to 23): recursive decimation in time with a generic butterfly per factor,
// O(N sum of the factors). Written here rather than taken from FFTW so that the
// runtime needs no other library; the turbulence generator is its one user.
#include <complex>
#include <vector>

namespace yamsc::runtime {

class Fft {
public:
    /// A transform of length n (>= 1): x_j = sum_k X_k exp(+2 pi i j k / n) (no 1/n).
    explicit Fft(int n);
    int size() const { return n_; }
    /// The inverse transform above of `in` into `out` (both of length n).
    void inverse(const std::complex<double>* in, std::complex<double>* out) const;

private:
    void work(std::complex<double>* out, const std::complex<double>* in, std::size_t stride,
              std::size_t level) const;
    int n_;
    std::vector<int> factors_;                  // the prime factors, smallest first
    std::vector<std::complex<double>> twiddle_; // exp(+2 pi i m / n)
};

} // namespace yamsc::runtime
