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

bool same(double a, double b) {
    return std::abs(a - b) <= 1e-12 * std::max({1.0, std::abs(a), std::abs(b)});
}

} // namespace

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
    if (alpha_.size() > 1) index_ = SegmentIndex(alpha_);

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
    const std::size_t i = index_.segment(x, a);
    const double w = (a - x[i]) / (x[i + 1] - x[i]);
    auto in = [&](const std::vector<double>& v) { return v[i] + w * (v[i + 1] - v[i]); };
    return {in(cl_), in(cd_), in(cm_), std::clamp(in(f_st_), 0.0, 1.0), in(cl_fs_)};
}

} // namespace yamsc::aero
