#pragma once
// Lüscher's RANLUX generator (M. Lüscher, Comput. Phys. Commun. 79 (1994) 100) as
// F. James implemented it (Comput. Phys. Commun. 79 (1994) 111): Marsaglia and
// Zaman's subtract-with-borrow x_n = x_{n-10} - x_{n-24} - c (mod 2^24), of which
// 24 numbers are delivered and p - 24 skipped (p = 24, 48, 97, 223, 389 for luxury
// levels 0..4); the 24 lags seeded by L'Ecuyer's multiplicative congruential
// generator (40014, mod 2147483563) from one integer, as James's RLUXGO does.
// OpenFAST's SeaState draws its random phases and amplitudes from it at level 3.
#include <array>
#include <cstdint>

namespace yamsc::runtime::hydro {

class Ranlux {
public:
    /// `seed` <= 0 is James's default seed 314159265. Throws std::invalid_argument
    /// for a luxury level outside 0..4.
    explicit Ranlux(int luxury = 3, std::int64_t seed = 0);
    /// The next number of the sequence, in (0, 1).
    double next();

private:
    std::array<std::int32_t, 24> lags_{}; // in units of 2^-24
    int i_ = 23, j_ = 9;                  // the long and short lag, 0-based, counting down
    int carry_ = 0;
    int delivered_ = 0; // numbers delivered in the current block of 24
    int skip_ = 0;
    std::int32_t step();
};

} // namespace yamsc::runtime::hydro
