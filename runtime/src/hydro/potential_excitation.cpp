#include <yamsc/hydro/potential_flow.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::runtime::hydro {
namespace {

constexpr double two_pi = 6.283185307179586;

/// The interval of `grid` (ascending) holding x and x's place in it, held at the ends.
std::pair<std::size_t, double> bracket(const std::vector<double>& grid, double x) {
    if (grid.size() == 1 || x <= grid.front()) return {0, 0.0};
    if (x >= grid.back()) return {grid.size() - 2, 1.0};
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(grid.begin(), grid.end(), x) - grid.begin());
    return {k - 1, (x - grid[k - 1]) / (grid[k] - grid[k - 1])};
}

} // namespace

std::array<std::complex<double>, 6> ExcitationTable::at(double w, double beta) const {
    const std::size_t nh = heading.size();
    if (omega.empty() || nh == 0 || force.size() != omega.size() * nh * 6)
        throw std::invalid_argument("excitation table: inconsistent sizes");
    // The heading into the table's range modulo 2 pi, as HydroDyn's GetAngleInRange.
    const double tol = 1e-6;
    while (beta < heading.front() - tol) beta += two_pi;
    while (beta > heading.back() + tol && beta - two_pi >= heading.front() - tol) beta -= two_pi;
    if (beta < heading.front() - tol || beta > heading.back() + tol)
        throw std::invalid_argument("the WAMIT .3 file does not cover the wave heading " +
                                    std::to_string(beta * 360 / two_pi) + " deg");
    const auto [f, sf] = bracket(omega, w);
    const auto [h, sh] = bracket(heading, beta);
    const std::size_t f1 = omega.size() > 1 ? f + 1 : f, h1 = nh > 1 ? h + 1 : h;
    auto x = [&](std::size_t fi, std::size_t hi, int i) {
        return force[(fi * nh + hi) * 6 + static_cast<std::size_t>(i)];
    };
    std::array<std::complex<double>, 6> out;
    for (int i = 0; i < 6; ++i)
        out[static_cast<std::size_t>(i)] = (1 - sf) * ((1 - sh) * x(f, h, i) + sh * x(f, h1, i)) +
                                           sf * ((1 - sh) * x(f1, h, i) + sh * x(f1, h1, i));
    return out;
}

} // namespace yamsc::runtime::hydro
