#pragma once
// The linearized Whipple bicycle of Meijaard, Papadopoulos, Ruina and Schwab,
// "Linearized dynamics equations for the balance and steer of a bicycle: a
// benchmark and review", Proc. R. Soc. A 463 (2007) 1955-1982: the matrices of
//     M q'' + v C1 q' + (g K0 + v^2 K2) q = 0,   q = (lean phi, steer delta),
// from the paper's parameters by its Appendix A formulas, and the eigenvalues of
// that equation. An oracle written from the paper alone, independent of yamsc.
#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <functional>

namespace bicycle {

/// Table 1 of the paper (benchmark axes: x forward, y right, z down; lengths from
/// the rear contact point; inertia tensors' own entries).
struct Parameters {
    double w = 1.02, c = 0.08, lambda = M_PI / 10, g = 9.81;
    double rR = 0.3, mR = 2, IRxx = 0.0603, IRyy = 0.12;
    double xB = 0.3, zB = -0.9, mB = 85, IBxx = 9.2, IByy = 11, IBzz = 2.8, IBxz = 2.4;
    double xH = 0.9, zH = -0.7, mH = 4, IHxx = 0.05892, IHyy = 0.06, IHzz = 0.00708,
           IHxz = -0.00756;
    double rF = 0.35, mF = 3, IFxx = 0.1405, IFyy = 0.28;
};

struct Matrices {
    Eigen::Matrix2d M, C1, K0, K2;
};

/// Appendix A of the paper, formula by formula.
inline Matrices matrices(const Parameters& p) {
    const double sl = std::sin(p.lambda), cl = std::cos(p.lambda);
    const double mT = p.mR + p.mB + p.mH + p.mF;
    const double xT = (p.xB * p.mB + p.xH * p.mH + p.w * p.mF) / mT;
    const double zT = (-p.rR * p.mR + p.zB * p.mB + p.zH * p.mH - p.rF * p.mF) / mT;
    const double ITxx = p.IRxx + p.IBxx + p.IHxx + p.IFxx + p.mR * p.rR * p.rR +
                        p.mB * p.zB * p.zB + p.mH * p.zH * p.zH + p.mF * p.rF * p.rF;
    const double ITxz =
        p.IBxz + p.IHxz - p.mB * p.xB * p.zB - p.mH * p.xH * p.zH + p.mF * p.w * p.rF;
    const double IRzz = p.IRxx, IFzz = p.IFxx;
    const double ITzz =
        IRzz + p.IBzz + p.IHzz + IFzz + p.mB * p.xB * p.xB + p.mH * p.xH * p.xH + p.mF * p.w * p.w;
    const double mA = p.mH + p.mF;
    const double xA = (p.xH * p.mH + p.w * p.mF) / mA;
    const double zA = (p.zH * p.mH - p.rF * p.mF) / mA;
    const double IAxx =
        p.IHxx + p.IFxx + p.mH * (p.zH - zA) * (p.zH - zA) + p.mF * (p.rF + zA) * (p.rF + zA);
    const double IAxz = p.IHxz - p.mH * (p.xH - xA) * (p.zH - zA) + p.mF * (p.w - xA) * (p.rF + zA);
    const double IAzz =
        p.IHzz + IFzz + p.mH * (p.xH - xA) * (p.xH - xA) + p.mF * (p.w - xA) * (p.w - xA);
    const double uA = (xA - p.w - p.c) * cl - zA * sl;
    const double IAll = mA * uA * uA + IAxx * sl * sl + 2 * IAxz * sl * cl + IAzz * cl * cl;
    const double IAlx = -mA * uA * zA + IAxx * sl + IAxz * cl;
    const double IAlz = mA * uA * xA + IAxz * sl + IAzz * cl;
    const double mu = p.c / p.w * cl;
    const double SR = p.IRyy / p.rR, SF = p.IFyy / p.rF, ST = SR + SF;
    const double SA = mA * uA + mu * mT * xT;

    Matrices m;
    m.M << ITxx, IAlx + mu * ITxz, IAlx + mu * ITxz, IAll + 2 * mu * IAlz + mu * mu * ITzz;
    m.K0 << mT * zT, -SA, -SA, -SA * sl;
    m.K2 << 0, (ST - mT * zT) / p.w * cl, 0, (SA + SF * sl) / p.w * cl;
    m.C1 << 0, mu * ST + SF * cl + ITxz / p.w * cl - mu * mT * zT, -(mu * ST + SF * cl),
        IAlz / p.w * cl + mu * (SA + ITzz / p.w * cl);
    return m;
}

/// Orders eigenvalues by real part, then imaginary part.
inline bool by_real_then_imag(std::complex<double> a, std::complex<double> b) {
    return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
}

/// The eigenvalues of a 4 x 4 matrix, sorted by_real_then_imag.
inline std::array<std::complex<double>, 4> sorted_eigenvalues(const Eigen::Matrix4d& A) {
    Eigen::EigenSolver<Eigen::Matrix4d> es(A, false);
    std::array<std::complex<double>, 4> out;
    for (int i = 0; i < 4; ++i) out[std::size_t(i)] = es.eigenvalues()[i];
    std::sort(out.begin(), out.end(), by_real_then_imag);
    return out;
}

/// The first-order form [0 I; -M^-1 (g K0 + v^2 K2)  -v M^-1 C1] at forward speed v.
inline Eigen::Matrix4d state_matrix(const Matrices& m, double g, double v) {
    Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
    A.topRightCorner<2, 2>().setIdentity();
    const Eigen::Matrix2d Minv = m.M.inverse();
    A.bottomLeftCorner<2, 2>() = -Minv * (g * m.K0 + v * v * m.K2);
    A.bottomRightCorner<2, 2>() = -Minv * (v * m.C1);
    return A;
}

/// The four eigenvalues at forward speed v, sorted by_real_then_imag.
inline std::array<std::complex<double>, 4> eigenvalues(const Matrices& m, double g, double v) {
    return sorted_eigenvalues(state_matrix(m, g, v));
}

/// The largest real part of the eigenvalues (the spectral abscissa).
inline double abscissa(const std::array<std::complex<double>, 4>& ev) {
    double a = -INFINITY;
    for (auto e : ev) a = std::max(a, e.real());
    return a;
}

/// A root of f in [a, b] where f changes sign, by bisection to the last bit of v.
inline double bisect(const std::function<double(double)>& f, double a, double b) {
    double fa = f(a);
    for (int i = 0; i < 200 && b - a > 1e-15 * b; ++i) {
        const double m = 0.5 * (a + b), fm = f(m);
        if ((fm < 0) == (fa < 0)) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    return 0.5 * (a + b);
}

/// Table 2 of the paper: the eigenvalues at v = 0, 1, ..., 10 m/s (real, imaginary).
/// Rows: speed; within a row the four eigenvalues sorted as eigenvalues() sorts them.
struct TableRow {
    double v;
    std::array<std::complex<double>, 4> ev;
};
inline std::array<TableRow, 11> published_table() {
    using C = std::complex<double>;
    // capsize (real), weave pair (re +- i im), castor (real); at v = 0 two real pairs.
    const double capsize[11] = {0,
                                -3.13423125066578,
                                -3.07158645641514,
                                -2.63366137253667,
                                -1.42944427361326,
                                -0.32286642900409,
                                -0.00406690076970,
                                0.10268170574766,
                                0.14327879765713,
                                0.15790184030917,
                                0.16105338653172};
    const double weave_re[11] = {0,
                                 3.52696170990070,
                                 2.68234517512745,
                                 1.70675605663975,
                                 0.41325331521125,
                                 -0.77534188219585,
                                 -1.52644486584142,
                                 -2.13875644258362,
                                 -2.69348683581097,
                                 -3.21675402252485,
                                 -3.72016840437287};
    const double weave_im[11] = {0,
                                 0.80774027519930,
                                 1.68066296590675,
                                 2.31582447384325,
                                 3.07910818603206,
                                 4.46486771378823,
                                 5.87673060598709,
                                 7.19525913329805,
                                 8.46037971396931,
                                 9.69377351531791,
                                 10.90681139476287};
    const double castor[11] = {0,
                               -7.11008014637442,
                               -8.67387984831735,
                               -10.35101467245920,
                               -12.15861426576450,
                               -14.07838969279820,
                               -16.08537123098030,
                               -18.15788466125262,
                               -20.27940894394569,
                               -22.43788559040858,
                               -24.62459635017404};
    std::array<TableRow, 11> t{};
    t[0] = {0,
            {C(-5.53094371765393), C(-3.13164324790656), C(3.13164324790656), C(5.53094371765393)}};
    for (int i = 1; i <= 10; ++i) {
        std::array<C, 4> ev{C(capsize[i]), C(weave_re[i], -weave_im[i]),
                            C(weave_re[i], weave_im[i]), C(castor[i])};
        std::sort(ev.begin(), ev.end(), by_real_then_imag);
        t[std::size_t(i)] = {double(i), ev};
    }
    return t;
}

/// The published weave and capsize speeds [m/s] (section 5 of the paper).
inline constexpr double weave_speed = 4.29238253634111;
inline constexpr double capsize_speed = 6.02426201538837;

} // namespace bicycle
