#pragma once
// The integration grid of a beam: the span [0, L] cut at the SID nodes and at the
// stations of the section properties (so that the piecewise-linear properties are
// smooth inside every segment), with Gauss-Legendre points inside each segment.
// Integrals of polynomial integrands of degree < 2 * kGaussPoints are exact; running
// integrals (the shape of a twisted beam from its curvature, the axial loads N(z) of
// Appendix C) use the Gauss points' integration matrix, exact for degree < kGaussPoints.
#include <vector>

namespace yamsc::beam {

constexpr int kGaussPoints = 8;

class Grid {
public:
    /// `nodes` evenly spaced SID nodes (>= 2) from 0 to `length`; `breaks` are
    /// extra cuts in [0, length] (the property stations).
    Grid(double length, int nodes, const std::vector<double>& breaks);

    /// ElastoDyn's discretization (its `Coeff`): `elements` equal elements, one point
    /// at each element centre weighted by the element length (midpoint rule), plus the
    /// root and the tip with weight 0. Running integrals are ElastoDyn's: each element
    /// adds half its length times its centre value on either side of its centre
    /// (`TwistedSF`, `AxRedBld`). Every point is a SID node.
    static Grid elements(double length, int elements);

    /// All points, increasing: each segment's left end, its Gauss points, ..., then L.
    const std::vector<double>& z() const { return z_; }
    std::size_t size() const { return z_.size(); }
    /// Quadrature weight of each point (0 at segment ends): integral = sum w_i f_i.
    const std::vector<double>& weights() const { return weight_; }
    /// Index in z() of each SID node, root to tip.
    const std::vector<std::size_t>& nodes() const { return nodes_; }

    /// The integral of f over [0, L]; f is sampled at z() (segment ends are not used).
    double integrate(const std::vector<double>& f) const;
    /// F(z_i) = integral of f from 0 to z_i, at every point.
    std::vector<double> running_integral(const std::vector<double>& f) const;
    /// F(z_i) = integral of f from z_i to L, at every point.
    std::vector<double> integral_to_tip(const std::vector<double>& f) const;

private:
    Grid() = default;
    bool midpoint_ = false; // ElastoDyn's element discretization
    std::vector<double> z_;
    std::vector<double> weight_; // quadrature weight of each point (0 at segment ends)
    std::vector<std::size_t> segment_start_;
    std::vector<std::size_t> nodes_;
};

} // namespace yamsc::beam
