// The oracles of the constrained models checked on their own, before any model
// uses them: the benchmark bicycle's matrices and eigenvalues against the numbers
// Meijaard et al. (2007) print, the linkages' closed forms against their loop
// equations and their Lagrange equations against energy, the rolling disk's
// closed forms against their defining balances.
#include "bicycle_benchmark.hpp"
#include "planar_linkages.hpp"
#include "rolling_disk.hpp"

#include <doctest/doctest.h>

namespace {

void check_entries(const Eigen::Matrix2d& got, const double (&want)[4], double tol) {
    for (int i = 0; i < 4; ++i) {
        INFO("entry " << i / 2 << "," << i % 2);
        CHECK(std::fabs(got(i / 2, i % 2) - want[i]) <= tol);
    }
}

} // namespace

TEST_CASE("bicycle oracle: Appendix A gives the matrices the paper prints") {
    const auto m = bicycle::matrices(bicycle::Parameters{});
    // Section 5.3 (14 decimals printed; M11 and K0 11 are exact).
    check_entries(m.M, {80.81722, 2.31941332208709, 2.31941332208709, 0.29784188199686}, 1e-13);
    check_entries(m.C1, {0, 33.86641391492494, -0.85035641456978, 1.68540397397560}, 1e-13);
    check_entries(m.K0, {-80.95, -2.59951685249872, -2.59951685249872, -0.80329488458618}, 1e-13);
    check_entries(m.K2, {0, 76.59734589573222, 0, 2.65431523794604}, 1e-13);
}

TEST_CASE("bicycle oracle: the eigenvalues of Table 2 from 0 to 10 m/s") {
    const bicycle::Parameters p;
    const auto m = bicycle::matrices(p);
    for (const auto& row : bicycle::published_table()) {
        const auto ev = bicycle::eigenvalues(m, p.g, row.v);
        for (std::size_t i = 0; i < 4; ++i) {
            INFO("v = " << row.v << ", eigenvalue " << ev[i] << " vs " << row.ev[i]);
            // 14 decimals printed: 1e-13 absolute is the table's own rounding.
            CHECK(std::abs(ev[i] - row.ev[i]) <= 1e-12);
        }
    }
}

TEST_CASE("bicycle oracle: weave and capsize speeds by root finding") {
    const bicycle::Parameters p;
    const auto m = bicycle::matrices(p);
    auto abscissa = [&](double v) { return bicycle::abscissa(bicycle::eigenvalues(m, p.g, v)); };
    const double weave = bicycle::bisect(abscissa, 4, 5);
    const double capsize = bicycle::bisect(abscissa, 6, 7);
    CHECK(std::fabs(weave - bicycle::weave_speed) < 1e-10);
    CHECK(std::fabs(capsize - bicycle::capsize_speed) < 1e-10);
    // The capsize speed independently: a real eigenvalue through zero is a root of
    // det(g K0 + v^2 K2) = 0, a quadratic in v^2 (K2's first column is zero).
    const Eigen::Matrix2d K0 = p.g * m.K0;
    // det = det(g K0) + v^2 (gK0_00 K2_11 - gK0_10 K2_01).
    const double a = K0(0, 0) * m.K2(1, 1) - K0(1, 0) * m.K2(0, 1);
    const double b = K0.determinant();
    CHECK(std::fabs(std::sqrt(-b / a) - bicycle::capsize_speed) < 1e-10);
    // Self-stable only between them.
    CHECK(abscissa(4.0) > 0);
    CHECK(abscissa(4.6) < 0);
    CHECK(abscissa(5.9) < 0);
    CHECK(abscissa(7.0) > 0);
}

TEST_CASE("four-bar oracle: Freudenstein's angles close the loop; derivatives are exact") {
    const linkage::FourBar fb;
    for (double th2 = 0; th2 < 2 * M_PI; th2 += 0.1) {
        const auto th = fb.angles(th2);
        CHECK(fb.loop(th).norm() < 1e-15);
        // First and second derivatives against central differences of the closed form.
        const auto s = fb.links(th2);
        const double h = 1e-4;
        const auto sp = fb.links(th2 + h), sm = fb.links(th2 - h);
        for (std::size_t i = 0; i < 3; ++i) {
            CHECK((s[i].dr - (sp[i].r - sm[i].r) / (2 * h)).norm() < 1e-8);
            CHECK((s[i].ddr - (sp[i].r - 2 * s[i].r + sm[i].r) / (h * h)).norm() < 1e-6);
            CHECK(std::fabs(s[i].db - (sp[i].b - sm[i].b) / (2 * h)) < 1e-7);
            CHECK(std::fabs(s[i].ddb - (sp[i].db - sm[i].db) / (2 * h)) < 1e-6);
        }
    }
}

TEST_CASE("slider-crank oracle: the slider relation closes the loop; derivatives are exact") {
    const linkage::SliderCrank sc;
    for (double th = 0; th < 2 * M_PI; th += 0.1) {
        const auto s = sc.links(th);
        CHECK(std::fabs(s[2].r.x() - sc.slider_x(th)) < 1e-15);
        CHECK(std::fabs(s[2].r.y() - sc.e) < 1e-15);
        CHECK(std::fabs(s[2].dr.y()) < 1e-15);
        CHECK(std::fabs(s[2].ddr.y()) < 1e-14);
        const double h = 1e-4;
        const auto sp = sc.links(th + h), sm = sc.links(th - h);
        for (std::size_t i = 0; i < 3; ++i) {
            CHECK((s[i].dr - (sp[i].r - sm[i].r) / (2 * h)).norm() < 1e-8);
            CHECK((s[i].ddr - (sp[i].r - 2 * s[i].r + sm[i].r) / (h * h)).norm() < 1e-6);
            CHECK(std::fabs(s[i].ddb - (sp[i].db - sm[i].db) / (2 * h)) < 1e-6);
        }
    }
}

TEST_CASE("linkage oracles: the Lagrange equation conserves energy") {
    auto drift = [](const auto& sys, double th0, double w0) {
        const double e0 = sys.energy(th0, w0);
        auto s = sys.integrate(th0, w0, 1e-4, 20000); // 2 s
        return std::fabs(sys.energy(s[0], s[1]) - e0) / std::fabs(e0);
    };
    const linkage::OneDof<linkage::FourBar> fb{};
    const linkage::OneDof<linkage::SliderCrank> sc{};
    CHECK(drift(fb, 0.3, 8.0) < 1e-11);
    CHECK(drift(sc, 0.3, 8.0) < 1e-11);
    // A wrong equation (the m' term halved) does not.
    struct Wrong : linkage::OneDof<linkage::FourBar> {
        double acceleration(double th, double w) const {
            const auto t = terms(th);
            return -(0.25 * t.dm * w * w + t.dV) / t.m;
        }
    };
    const Wrong wrong{};
    double th = 0.3, w = 8.0;
    const double e0 = wrong.energy(th, w);
    for (int i = 0; i < 20000; ++i) { // explicit Euler is enough to see it
        const double a = wrong.acceleration(th, w);
        th += 1e-4 * w;
        w += 1e-4 * a;
    }
    CHECK(std::fabs(wrong.energy(th, w) - e0) / e0 > 1e-3);
}

TEST_CASE("rolling disk oracle: steady turning and the upright bound") {
    const disk::Disk d;
    for (double phi : {-0.4, 0.1, 0.3}) {
        for (double ws : {5.0, 20.0, 60.0}) {
            const double W = d.steady_yaw_rate(phi, ws);
            const double res = d.I() * W * W * std::sin(phi) * std::cos(phi) -
                               (d.J() + d.m * d.r * d.r) * ws * W * std::cos(phi) -
                               d.m * d.g * d.r * std::sin(phi);
            CHECK(std::fabs(res) < 1e-12 * d.m * d.g * d.r);
            CHECK(W * phi < 0); // leaning right (phi > 0) turns right
        }
    }
    // Uniform disk: v^2 > g r / 3.
    CHECK(d.critical_spin() * d.r == doctest::Approx(std::sqrt(d.g * d.r / 3)).epsilon(1e-15));
    CHECK(d.lean_eigenvalue_squared(0.99 * d.critical_spin()) > 0);
    CHECK(d.lean_eigenvalue_squared(1.01 * d.critical_spin()) < 0);
}
