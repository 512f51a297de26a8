#pragma once
// Closed forms of a thin disk rolling without slip on a horizontal plane (Neimark &
// Fufaev, "Dynamics of nonholonomic systems", ch. II; O'Reilly, "The dynamics of
// rolling disks and sliding disks", Nonlinear Dynamics 10, 1996), derived from
// the balance of angular momentum about the centre in the lean frame
// (e1 forward and horizontal, e2 along the axle, e3 from the contact to the centre):
// - steady turning at lean phi (rotation about e1; phi > 0 leans to the right),
//   yaw rate Omega and axle spin ws = Omega sin phi + theta' (the absolute
//   angular velocity's axle component):
//       I Omega^2 sin phi cos phi - (J + m r^2) ws Omega cos phi - m g r sin phi = 0,
//   the centre on a circle of radius r ws / Omega;
// - upright straight rolling at spin ws0 (speed r ws0): the linearized lean
//       (I + m r^2) phi'' + ((J + m r^2) J ws0^2 / I - m g r) phi = 0,
//   stable (oscillating) iff ws0^2 > m g r I / (J (J + m r^2)); for a uniform disk
//   (I = m r^2 / 4, J = m r^2 / 2) that is v^2 > g r / 3.
#include <cmath>

namespace disk {

struct Disk {
    double m = 2.0, r = 0.3, g = 9.81;
    double I() const { return m * r * r / 4; } // about a diameter
    double J() const { return m * r * r / 2; } // about the axle

    /// The yaw rate of steady turning at lean phi and spin ws: the root of the
    /// quadratic in Omega that tends to the gyroscopic one as ws grows.
    double steady_yaw_rate(double phi, double ws) const {
        const double a = I() * std::sin(phi) * std::cos(phi);
        const double b = -(J() + m * r * r) * ws * std::cos(phi);
        const double c = -m * g * r * std::sin(phi);
        // a W^2 + b W + c = 0; the root continuous with -c/b as a -> 0.
        const double disc = std::sqrt(b * b - 4 * a * c);
        return (2 * c) / (-b - (b < 0 ? -disc : disc));
    }
    /// The spin below which upright rolling is unstable.
    double critical_spin() const { return std::sqrt(m * g * r * I() / (J() * (J() + m * r * r))); }
    /// The lean's eigenvalue squared about upright rolling at spin ws0 (negative: oscillation).
    double lean_eigenvalue_squared(double ws0) const {
        return -((J() + m * r * r) * J() * ws0 * ws0 / I() - m * g * r) / (I() + m * r * r);
    }
};

} // namespace disk
