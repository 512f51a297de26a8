// RANLUX from the published algorithm (see ranlux.hpp): integer lags of 24 bits, so
// the sequence is exact and the same in any precision.
#include "yamsc/hydro/ranlux.hpp"

#include <stdexcept>

namespace yamsc::runtime::hydro {

namespace {
constexpr std::int32_t two24 = 1 << 24;
constexpr double two_m24 = 1.0 / two24;
constexpr double two_m12 = 1.0 / 4096;
constexpr std::int64_t default_seed = 314159265;
// The numbers skipped after each block of 24 delivered, per luxury level.
constexpr std::array<int, 5> skipped{0, 24, 73, 199, 365};
} // namespace

Ranlux::Ranlux(int luxury, std::int64_t seed) {
    if (luxury < 0 || luxury >= static_cast<int>(skipped.size()))
        throw std::invalid_argument("RANLUX: the luxury level must be 0 to 4");
    if (seed < 0 || seed > 2147483647)
        throw std::invalid_argument("RANLUX: the seed must be 0 to 2^31 - 1");
    skip_ = skipped[static_cast<std::size_t>(luxury)];
    // L'Ecuyer's generator by Schrage's factorization (a = 40014, m = 2147483563).
    std::int64_t s = seed == 0 ? default_seed : seed;
    for (auto& lag : lags_) {
        const std::int64_t k = s / 53668;
        s = 40014 * (s - k * 53668) - k * 12211;
        if (s < 0) s += 2147483563;
        lag = static_cast<std::int32_t>(s % two24);
    }
    carry_ = lags_[23] == 0 ? 1 : 0;
}

std::int32_t Ranlux::step() {
    std::int32_t x =
        lags_[static_cast<std::size_t>(j_)] - lags_[static_cast<std::size_t>(i_)] - carry_;
    carry_ = x < 0 ? 1 : 0;
    if (x < 0) x += two24;
    lags_[static_cast<std::size_t>(i_)] = x;
    i_ = i_ == 0 ? 23 : i_ - 1;
    j_ = j_ == 0 ? 23 : j_ - 1;
    return x;
}

double Ranlux::next() {
    // OpenFAST draws one number a call; its fill-in of the low bits of small numbers
    // takes the short lag as it was before the call.
    const std::int32_t fill = lags_[static_cast<std::size_t>(j_)];
    double r = step() * two_m24;
    if (++delivered_ == 24) {
        delivered_ = 0;
        for (int n = 0; n < skip_; ++n) step();
    }
    if (r < two_m12) r += two_m24 * (fill * two_m24);
    if (r == 0) r = two_m24 * two_m24;
    return r;
}

} // namespace yamsc::runtime::hydro
