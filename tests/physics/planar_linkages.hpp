#pragma once
// Closed-form oracles of two planar one-DOF linkages, independent of yamsc: the
// four-bar (Freudenstein's equation) and the offset slider-crank, with the exact
// first and second derivatives of every link's position and angle in the crank
// angle, and the Lagrange equation in that one coordinate,
//     m(th) th'' + m'(th) th'^2 / 2 + V'(th) = 0,
//     m = sum(m_i |dr_i/dth|^2 + I_i (db_i/dth)^2),  V = sum(m_i g z_i).
// The plane is x (horizontal), z (up); angles turn x towards z.
#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <vector>

namespace linkage {

/// A link's centre of mass and angle, and their first and second derivatives in th.
struct LinkState {
    Eigen::Vector2d r, dr, ddr;
    double b = 0, db = 0, ddb = 0;
};

struct Link {
    double m, I; // mass [kg], moment of inertia about the centre of mass [kg m^2]
};

/// A uniform bar of length L and mass m: I = m L^2 / 12 about its middle.
inline Link bar(double m, double L) {
    return {m, m * L * L / 12};
}

inline Eigen::Vector2d dir(double b) {
    return {std::cos(b), std::sin(b)};
}
inline Eigen::Vector2d perp(double b) {
    return {-std::sin(b), std::cos(b)};
}

/// Four-bar: ground pivots O2 = (0, 0) and O4 = (d, 0); crank a (angle th2), coupler b
/// (th3), rocker c (th4), all absolute angles; the open branch (th4 from the larger root).
struct FourBar {
    double a = 0.1, b = 0.4, c = 0.3, d = 0.35;
    Link crank = bar(1.0, 0.1), coupler = bar(2.0, 0.4), rocker = bar(1.5, 0.3);

    /// Freudenstein: K1 cos th4 - K2 cos th2 + K3 = cos(th2 - th4), solved for th4.
    double rocker_angle(double th2) const {
        const double K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2 * a * c);
        // A cos th4 + B sin th4 = C
        const double A = K1 - std::cos(th2), B = -std::sin(th2), C = K2 * std::cos(th2) - K3;
        return 2 * std::atan2(B + std::sqrt(A * A + B * B - C * C), A + C);
    }
    /// The three angles (th2, th3, th4) with th3 from the loop a e2 + b e3 = d + c e4.
    std::array<double, 3> angles(double th2) const {
        const double th4 = rocker_angle(th2);
        const Eigen::Vector2d v = Eigen::Vector2d(d, 0) + c * dir(th4) - a * dir(th2);
        return {th2, std::atan2(v.y(), v.x()), th4};
    }
    /// The loop's residual a e2 + b e3 - c e4 - d (zero on the mechanism).
    Eigen::Vector2d loop(const std::array<double, 3>& th) const {
        return a * dir(th[0]) + b * dir(th[1]) - c * dir(th[2]) - Eigen::Vector2d(d, 0);
    }
    /// Crank, coupler and rocker with their derivatives in th2.
    std::array<LinkState, 3> links(double th2) const {
        const auto th = angles(th2);
        // d/dth2 of the loop: a p2 + b p3 th3' - c p4 th4' = 0; second derivative
        // -a e2 + b (p3 th3'' - e3 th3'^2) - c (p4 th4'' - e4 th4'^2) = 0.
        Eigen::Matrix2d J;
        J.col(0) = b * perp(th[1]);
        J.col(1) = -c * perp(th[2]);
        const Eigen::Vector2d d1 = J.lu().solve(-a * perp(th[0]));
        const Eigen::Vector2d rhs2 =
            a * dir(th[0]) + b * dir(th[1]) * d1[0] * d1[0] - c * dir(th[2]) * d1[1] * d1[1];
        const Eigen::Vector2d d2 = J.lu().solve(rhs2);
        std::array<LinkState, 3> s;
        s[0] = {0.5 * a * dir(th[0]), 0.5 * a * perp(th[0]), -0.5 * a * dir(th[0]), th[0], 1, 0};
        const double w3 = d1[0], a3 = d2[0], w4 = d1[1], a4 = d2[1];
        s[1].r = a * dir(th[0]) + 0.5 * b * dir(th[1]);
        s[1].dr = a * perp(th[0]) + 0.5 * b * perp(th[1]) * w3;
        s[1].ddr = -a * dir(th[0]) + 0.5 * b * (perp(th[1]) * a3 - dir(th[1]) * w3 * w3);
        s[1].b = th[1];
        s[1].db = w3;
        s[1].ddb = a3;
        s[2].r = Eigen::Vector2d(d, 0) + 0.5 * c * dir(th[2]);
        s[2].dr = 0.5 * c * perp(th[2]) * w4;
        s[2].ddr = 0.5 * c * (perp(th[2]) * a4 - dir(th[2]) * w4 * w4);
        s[2].b = th[2];
        s[2].db = w4;
        s[2].ddb = a4;
        return s;
    }
    std::vector<Link> masses() const { return {crank, coupler, rocker}; }
};

/// Offset slider-crank: crank a about the origin (angle th), rod l (absolute angle phi)
/// from the crank pin to the slider pin at height e, the slider (mass ms) along x:
///     x = a cos th + sqrt(l^2 - (a sin th - e)^2),  sin phi = (e - a sin th) / l.
struct SliderCrank {
    double a = 0.1, l = 0.35, e = 0.02;
    Link crank = bar(1.0, 0.1), rod = bar(1.5, 0.35), slider{2.0, 0.0};

    double slider_x(double th) const {
        const double h = a * std::sin(th) - e;
        return a * std::cos(th) + std::sqrt(l * l - h * h);
    }
    double rod_angle(double th) const { return std::asin((e - a * std::sin(th)) / l); }

    std::array<LinkState, 3> links(double th) const {
        const double phi = rod_angle(th), cp = std::cos(phi);
        // l sin phi = e - a sin th: l cos phi phi' = -a cos th;
        // l (cos phi phi'' - sin phi phi'^2) = a sin th.
        const double w = -a * std::cos(th) / (l * cp);
        const double al = (a * std::sin(th) + l * std::sin(phi) * w * w) / (l * cp);
        std::array<LinkState, 3> s;
        s[0] = {0.5 * a * dir(th), 0.5 * a * perp(th), -0.5 * a * dir(th), th, 1, 0};
        s[1].r = a * dir(th) + 0.5 * l * dir(phi);
        s[1].dr = a * perp(th) + 0.5 * l * perp(phi) * w;
        s[1].ddr = -a * dir(th) + 0.5 * l * (perp(phi) * al - dir(phi) * w * w);
        s[1].b = phi;
        s[1].db = w;
        s[1].ddb = al;
        // the slider pin: a e(th) + l e(phi), its z fixed at e.
        s[2].r = a * dir(th) + l * dir(phi);
        s[2].dr = a * perp(th) + l * perp(phi) * w;
        s[2].ddr = -a * dir(th) + l * (perp(phi) * al - dir(phi) * w * w);
        s[2].b = 0;
        return s;
    }
    std::vector<Link> masses() const { return {crank, rod, slider}; }
};

/// The Lagrange equation of a one-DOF linkage in its coordinate: th''(th, th').
template <class Mechanism> struct OneDof {
    Mechanism mech;
    double g = 9.81;

    struct Terms {
        double m, dm, dV, V;
    };
    Terms terms(double th) const {
        const auto s = mech.links(th);
        const auto links = mech.masses();
        Terms t{0, 0, 0, 0};
        for (std::size_t i = 0; i < s.size(); ++i) {
            t.m += links[i].m * s[i].dr.squaredNorm() + links[i].I * s[i].db * s[i].db;
            t.dm += 2 * (links[i].m * s[i].dr.dot(s[i].ddr) + links[i].I * s[i].db * s[i].ddb);
            t.dV += links[i].m * g * s[i].dr.y();
            t.V += links[i].m * g * s[i].r.y();
        }
        return t;
    }
    double acceleration(double th, double w) const {
        const Terms t = terms(th);
        return -(0.5 * t.dm * w * w + t.dV) / t.m;
    }
    double energy(double th, double w) const {
        const Terms t = terms(th);
        return 0.5 * t.m * w * w + t.V;
    }
    /// Classical Runge-Kutta of order 4 from (th, w) over n steps of h.
    std::array<double, 2> integrate(double th, double w, double h, long n) const {
        for (long i = 0; i < n; ++i) {
            const double k1t = w, k1w = acceleration(th, w);
            const double k2t = w + 0.5 * h * k1w, k2w = acceleration(th + 0.5 * h * k1t, k2t);
            const double k3t = w + 0.5 * h * k2w, k3w = acceleration(th + 0.5 * h * k2t, k3t);
            const double k4t = w + h * k3w, k4w = acceleration(th + h * k3t, k4t);
            th += h / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
            w += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
        }
        return {th, w};
    }
};

} // namespace linkage
