#include "beam/grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace yamsc::beam {

namespace {

constexpr std::size_t kP = kGaussPoints;
const double kPi = std::acos(-1.0);

/// Gauss-Legendre abscissae and weights on [-1, 1] (Newton on the Legendre polynomial).
struct GaussRule {
    std::array<double, kP> x{}, w{};
    // q[i][j] = integral from -1 to x[i] of the j-th Lagrange basis polynomial on x:
    // the running integral of an interpolated function at the Gauss points.
    std::array<std::array<double, kP>, kP> q{};

    GaussRule() {
        for (std::size_t i = 0; i < kP; ++i) {
            double t = std::cos(kPi * (static_cast<double>(i) + 0.75) / (kP + 0.5));
            double dp = 1;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1, p1 = t; // P_0, P_1; recurrence up to P_n
                for (std::size_t n = 2; n <= kP; ++n) {
                    double p2 = ((2.0 * n - 1) * t * p1 - (n - 1.0) * p0) / static_cast<double>(n);
                    p0 = p1;
                    p1 = p2;
                }
                dp = kP * (t * p1 - p0) / (t * t - 1);
                double step = p1 / dp;
                t -= step;
                if (std::fabs(step) < 1e-16) break;
            }
            x[kP - 1 - i] = t; // increasing order
            w[kP - 1 - i] = 2 / ((1 - t * t) * dp * dp);
        }
        for (std::size_t i = 0; i < kP; ++i)
            for (std::size_t j = 0; j < kP; ++j) {
                double half = (x[i] + 1) / 2, sum = 0; // map [-1, x_i] onto the rule
                for (std::size_t m = 0; m < kP; ++m)
                    sum += w[m] * lagrange(j, -1 + half * (x[m] + 1));
                q[i][j] = half * sum;
            }
    }

    double lagrange(std::size_t j, double t) const {
        double v = 1;
        for (std::size_t m = 0; m < kP; ++m)
            if (m != j) v *= (t - x[m]) / (x[j] - x[m]);
        return v;
    }
};

const GaussRule& rule() {
    static const GaussRule r;
    return r;
}

} // namespace

Grid::Grid(double length, int nodes, const std::vector<double>& breaks) {
    std::vector<double> cuts;
    for (int i = 0; i < nodes; ++i) cuts.push_back(length * i / (nodes - 1));
    for (double b : breaks)
        if (b > 0 && b < length) cuts.push_back(b);
    std::sort(cuts.begin(), cuts.end());
    const double tol = 1e-9 * length; // a station on a node is the same cut
    std::vector<double> unique;
    for (double c : cuts)
        if (unique.empty() || c - unique.back() > tol) unique.push_back(c);
    unique.back() = length;

    const GaussRule& g = rule();
    std::size_t next_node = 0;
    for (std::size_t s = 0; s < unique.size(); ++s) {
        const double a = unique[s];
        if (next_node < static_cast<std::size_t>(nodes) &&
            std::fabs(a - length * static_cast<double>(next_node) / (nodes - 1)) <= tol) {
            nodes_.push_back(z_.size());
            ++next_node;
        }
        if (s + 1 == unique.size()) break;
        segment_start_.push_back(z_.size());
        z_.push_back(a);
        weight_.push_back(0);
        const double h = unique[s + 1] - a;
        for (std::size_t i = 0; i < kP; ++i) {
            z_.push_back(a + h * (g.x[i] + 1) / 2);
            weight_.push_back(h * g.w[i] / 2);
        }
    }
    z_.push_back(length);
    weight_.push_back(0);
}

Grid Grid::elements(double length, int elements) {
    Grid g;
    g.midpoint_ = true;
    const double dr = length / elements;
    g.z_.push_back(0);
    g.weight_.push_back(0);
    for (int j = 0; j < elements; ++j) {
        g.z_.push_back((j + 0.5) * dr);
        g.weight_.push_back(dr);
    }
    g.z_.push_back(length);
    g.weight_.push_back(0);
    for (std::size_t i = 0; i < g.z_.size(); ++i) g.nodes_.push_back(i);
    return g;
}

double Grid::integrate(const std::vector<double>& f) const {
    double sum = 0;
    for (std::size_t i = 0; i < z_.size(); ++i) sum += weight_[i] * f[i];
    return sum;
}

std::vector<double> Grid::running_integral(const std::vector<double>& f) const {
    std::vector<double> out(z_.size(), 0.0);
    if (midpoint_) {
        // The root (index 0) and the tip carry no weight: F(root) = 0, and the tip
        // adds the outer half of the last element, as ElastoDyn's TipNode.
        for (std::size_t i = 1; i < z_.size(); ++i)
            out[i] = out[i - 1] + 0.5 * weight_[i - 1] * f[i - 1] + 0.5 * weight_[i] * f[i];
        return out;
    }
    const GaussRule& g = rule();
    for (std::size_t s = 0; s < segment_start_.size(); ++s) {
        const std::size_t a = segment_start_[s], end = a + kP + 1;
        const double h = z_[end] - z_[a];
        double total = 0;
        for (std::size_t i = 0; i < kP; ++i) {
            double part = 0;
            for (std::size_t j = 0; j < kP; ++j) part += g.q[i][j] * f[a + 1 + j];
            out[a + 1 + i] = out[a] + h / 2 * part;
            total += weight_[a + 1 + i] * f[a + 1 + i];
        }
        out[end] = out[a] + total;
    }
    return out;
}

std::vector<double> Grid::integral_to_tip(const std::vector<double>& f) const {
    std::vector<double> out = running_integral(f);
    const double total = out.back();
    for (double& v : out) v = total - v;
    return out;
}

} // namespace yamsc::beam
