// Per-airfoil data of the unsteady models, computed once as AirfoilInfo's
// CalculateUACoeffs does at initialization.
#include "unsteady_math.hpp"
#include "yamsc/aero/unsteady_airfoil.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::aero {

using unsteady_detail::pi;
using unsteady_detail::wrap_pi;

namespace {

constexpr double deg = pi / 180;

// Linear interpolation in increasing x, constant beyond the ends (NWTC InterpStp).
double interp_clamped(double xv, const std::vector<double>& x, const std::vector<double>& y) {
    if (xv <= x.front()) return y.front();
    if (xv >= x.back()) return y.back();
    const std::size_t i = std::upper_bound(x.begin(), x.end(), xv) - x.begin() - 1;
    return y[i] + (xv - x[i]) / (x[i + 1] - x[i]) * (y[i + 1] - y[i]);
}

// NWTC kernelSmoothing with the triweight kernel.
std::vector<double> smooth_triweight(const std::vector<double>& x, const std::vector<double>& f,
                                     double radius) {
    std::vector<double> out(x.size(), 0.0);
    for (std::size_t j = 0; j < x.size(); ++j) {
        double k_sum = 0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double u = std::clamp((x[i] - x[j]) / radius, -1.0, 1.0);
            const double k = 35.0 / 32.0 * std::pow(1 - u * u, 3);
            k_sum += k;
            out[j] += k * f[i];
        }
        if (k_sum > 0) out[j] /= k_sum;
    }
    return out;
}

bool same(double a, double b) {
    return std::abs(a - b) <= 1e-12 * std::max({1.0, std::abs(a), std::abs(b)});
}

} // namespace

AttachedRange attached_range_defaults(const PolarTable& t, double cd0) {
    // Written with AirfoilInfo's 1-based indices: A(i) is t.alpha[i-1], S(i) the i-th
    // segment's midpoint angle and smoothed Cn slope.
    const int n = static_cast<int>(t.alpha.size());
    if (n < 4) throw std::invalid_argument("unsteady aerodynamics: a table needs 4 rows or more");
    const double limit = 20 * deg;
    auto A = [&](int i) { return t.alpha[i - 1]; };
    std::vector<double> cn(n), mid(n - 1), cn_slope_raw(n - 1);
    for (int i = 0; i < n; ++i)
        cn[i] = t.cl[i] * std::cos(t.alpha[i]) + (t.cd[i] - cd0) * std::sin(t.alpha[i]);
    for (int i = 0; i + 1 < n; ++i) {
        cn_slope_raw[i] = (cn[i + 1] - cn[i]) / (t.alpha[i + 1] - t.alpha[i]);
        mid[i] = 0.5 * (t.alpha[i + 1] + t.alpha[i]);
    }
    const std::vector<double> slope = smooth_triweight(mid, cn_slope_raw, 2 * deg);
    auto M = [&](int i) { return mid[i - 1]; };
    auto S = [&](int i) { return slope[i - 1]; };

    int i_cd_min = 0; // first minimum of Cd within +-20 deg
    for (int i = 1; i <= n; ++i)
        if (std::abs(A(i)) <= limit && (i_cd_min == 0 || t.cd[i - 1] < t.cd[i_cd_min - 1]))
            i_cd_min = i;
    if (i_cd_min == 0) i_cd_min = 1;
    const double alpha_cd_min = A(i_cd_min);
    const double slope_cd_min = interp_clamped(alpha_cd_min, mid, slope);

    int i_high_limit = 0, i_low_limit = 0;
    for (int i = 1; i <= n - 1; ++i) {
        if (M(i) < limit && (i_high_limit == 0 || M(i) > M(i_high_limit))) i_high_limit = i;
        if (M(i) > -limit && (i_low_limit == 0 || M(i) < M(i_low_limit))) i_low_limit = i;
    }
    i_high_limit = std::min(i_high_limit + 1, n - 1);
    i_low_limit = std::max(i_low_limit - 1, 1);
    if (i_high_limit - i_low_limit < 3) i_high_limit = std::min(i_low_limit + 2, n - 1);
    if (i_high_limit - i_low_limit < 3) i_low_limit = std::max(i_high_limit - 2, 1);

    AttachedRange r;
    int i_high = i_high_limit < i_cd_min ? n - 1 : i_high_limit;
    // Walking the segments from `from` to `to`, the last one before the smoothed slope
    // falls below 90 % of its largest value so far (from the slope at Cd's minimum on).
    auto last_attached = [&](int from, int to, int dir) {
        double max_slope = slope_cd_min;
        int last = from;
        for (int row = from; dir > 0 ? row <= to : row >= to; row += dir) {
            last = row;
            if (S(row) > max_slope)
                max_slope = S(row);
            else if (S(row) < 0.9 * max_slope)
                break;
        }
        return last;
    };
    int i_high2 = last_attached(i_cd_min, i_high, +1);
    if (i_high2 == i_cd_min) {
        r.alpha_upper = alpha_cd_min;
    } else {
        i_high2 = std::min(std::max(1, i_high2 - 1), n - 1);
        r.alpha_upper = M(i_high2);
    }

    int i_low = i_low_limit;
    i_high = std::max(1, std::min({i_high2, i_cd_min, n - 1}));
    if (i_high < i_low) i_low = 1;
    int i_low2 = last_attached(i_high, i_low, -1);
    if (i_low2 == i_cd_min) {
        r.alpha_lower = alpha_cd_min;
    } else {
        i_low2 = std::min(std::max(1, i_low2 + 1), n - 1);
        r.alpha_lower = M(i_low2);
    }

    // Least-squares lines through Cn and Cl on the attached range less a margin.
    const double margin = 0.2 * (r.alpha_upper - r.alpha_lower);
    i_low2 = i_low_limit;
    while (i_low2 < i_high_limit - 1 && A(i_low2) < r.alpha_lower + margin) ++i_low2;
    i_high2 = i_high_limit;
    while (i_high2 > i_low2 + 1 && A(i_high2) > r.alpha_upper - margin) --i_high2;
    double sx = 0, sxx = 0, sn = 0, sxn = 0, sl = 0, sxl = 0;
    const int m = i_high2 - i_low2 + 1;
    for (int i = i_low2; i <= i_high2; ++i) {
        const double x = A(i);
        sx += x;
        sxx += x * x;
        sn += cn[i - 1];
        sxn += x * cn[i - 1];
        sl += t.cl[i - 1];
        sxl += x * t.cl[i - 1];
    }
    const double det = m * sxx - sx * sx;
    r.cn_alpha = (m * sxn - sx * sn) / det;
    r.cl_alpha = (m * sxl - sx * sl) / det;
    const double cn_at_0 = (sn - r.cn_alpha * sx) / m;
    r.alpha0 = r.cn_alpha != 0 ? -cn_at_0 / r.cn_alpha : 0.0;
    return r;
}

UnsteadyAirfoil::UnsteadyAirfoil(const Airfoil& airfoil) {
    if (airfoil.tables.empty() || airfoil.tables.front().alpha.empty())
        throw std::invalid_argument("unsteady aerodynamics: airfoil '" + airfoil.name +
                                    "' has no table");
    const PolarTable& t = airfoil.tables.front();
    has_unsteady_ = t.unsteady.has_value();
    if (has_unsteady_) k_ = *t.unsteady;
    bool all_same = true;
    for (std::size_t i = 1; i < t.alpha.size(); ++i)
        all_same = all_same && t.cl[i] == t.cl[0] && t.cd[i] == t.cd[0];
    constant_ = t.alpha.size() < 3 || all_same;
    alpha_ = t.alpha;
    cl_ = t.cl;
    cd_ = t.cd;
    has_cm_ = !t.cm.empty();
    cm_ = has_cm_ ? t.cm : std::vector<double>(t.alpha.size(), 0.0);
    cutout_blend_ = std::max(0.0, std::abs(k_.UACutout) - 5 * deg);

    // The separation function on Cl and the fully separated Cl (AirfoilInfo's
    // ComputeUASeparationFunction_onCl; Oye's and HGM's models).
    const std::size_t n = alpha_.size();
    f_st_.assign(n, 0.0);
    cl_fs_ = cl_;
    const double a0 = k_.alpha0, slope = k_.C_lalpha;
    if (slope == 0) return; // UA is off for this airfoil (UA_TurnOff_param)
    for (std::size_t i = 0; i < n; ++i) {
        if (same(alpha_[i], a0)) {
            f_st_[i] = 1;
            cl_fs_[i] = cl_[i] / 2;
            continue;
        }
        const double ratio = std::max(0.0, cl_[i] / (slope * (alpha_[i] - a0)));
        double f = std::pow(2 * std::sqrt(ratio) - 1, 2);
        if (f < 1) {
            f = std::max(0.0, f);
            cl_fs_[i] = (cl_[i] - slope * (alpha_[i] - a0) * f) / (1 - f);
        } else {
            f = 1;
            cl_fs_[i] = cl_[i] / 2;
        }
        f_st_[i] = f;
    }
    // Fully separated beyond the last minimum of f below alphaLower and the first one
    // above alphaUpper (ComputeUASeparationFunction_zero).
    std::size_t i_low = n, i_high = n;
    for (std::size_t i = 0; i < n; ++i)
        if (alpha_[i] < k_.alphaLower && (i_low == n || f_st_[i] <= f_st_[i_low])) i_low = i;
    for (std::size_t i = 0; i < n; ++i)
        if (alpha_[i] > k_.alphaUpper && (i_high == n || f_st_[i] < f_st_[i_high])) i_high = i;
    for (std::size_t i = 0; i < n; ++i) {
        if ((i_low < n && i <= i_low) || (i_high < n && i >= i_high)) {
            cl_fs_[i] = cl_[i];
            f_st_[i] = 0;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        const double cl_inv = slope * (alpha_[i] - a0);
        f_st_[i] = same(cl_inv, cl_fs_[i])
                       ? 1.0
                       : std::clamp((cl_[i] - cl_fs_[i]) / (cl_inv - cl_fs_[i]), 0.0, 1.0);
    }
}

bool UnsteadyAirfoil::supports(UnsteadyModel model) const {
    if (!has_unsteady_ || constant_) return false;
    switch (model) {
    case UnsteadyModel::minnema_pierce:
        return k_.C_nalpha != 0;
    case UnsteadyModel::oye:
        return k_.C_lalpha != 0 && *std::max_element(f_st_.begin(), f_st_.end()) > 0;
    default:
        return false;
    }
}

UnsteadyAirfoil::Point UnsteadyAirfoil::at(double alpha) const {
    const auto& x = alpha_;
    if (x.size() == 1) return {cl_[0], cd_[0], cm_[0], std::clamp(f_st_[0], 0.0, 1.0), cl_fs_[0]};
    const double a = std::clamp(wrap_pi(alpha), x.front(), x.back());
    const std::size_t i =
        std::min<std::size_t>(std::upper_bound(x.begin(), x.end(), a) - x.begin(), x.size() - 1) -
        1;
    const double w = (a - x[i]) / (x[i + 1] - x[i]);
    auto in = [&](const std::vector<double>& v) { return v[i] + w * (v[i + 1] - v[i]); };
    return {in(cl_), in(cd_), in(cm_), std::clamp(in(f_st_), 0.0, 1.0), in(cl_fs_)};
}

} // namespace yamsc::aero
