// The unsteady constants and the separation function of an airfoil table as
// AeroDyn's AirfoilInfo computes them (CalculateUACoeffs and the routines it calls).
// Indices below are 1-based, as in AirfoilInfo, so that each step can be compared
// with it; at(v, i) reads v[i - 1].
#include "aerodyn_input/airfoil.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace yamsc::aerodyn_input {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi / 180;

double at(const std::vector<double>& v, int i) {
    return v[static_cast<std::size_t>(i - 1)];
}
double& at(std::vector<double>& v, int i) {
    return v[static_cast<std::size_t>(i - 1)];
}
int size(const std::vector<double>& v) {
    return static_cast<int>(v.size());
}

/// OpenFAST's EqualRealNos in double precision (its default build).
bool equal(double a, double b) {
    const double tol = 100 * 2.220446049250313e-16 / 2;
    return std::fabs(a - b) <= std::max(std::fabs(a + b), 1.0) * tol;
}

/// Linear interpolation clamped to the ends (NWTC's InterpStp).
double interp_clamped(double x, const std::vector<double>& xs, const std::vector<double>& ys) {
    const int n = size(xs);
    if (std::isnan(x)) return x;
    if (x <= at(xs, 1)) return at(ys, 1);
    if (x >= at(xs, n)) return at(ys, n);
    const int i =
        static_cast<int>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin()); // xs(i) <= x
    return (at(ys, i + 1) - at(ys, i)) * (x - at(xs, i)) / (at(xs, i + 1) - at(xs, i)) + at(ys, i);
}

/// Linear interpolation, extrapolated beyond the ends (NWTC's InterpExtrapStp, on
/// three points that need not rise).
double interp_extrapolated(double x, const double (&xs)[3], const double (&ys)[3]) {
    int i = 1;
    if (x <= xs[0]) {
        i = 1;
    } else if (x >= xs[2]) {
        i = 2;
    } else {
        for (int guard = 0; guard < 4; ++guard) {
            if (x < xs[i - 1])
                --i;
            else if (x >= xs[i])
                ++i;
            else
                break;
            i = std::clamp(i, 1, 2);
        }
    }
    return (ys[i] - ys[i - 1]) * (x - xs[i - 1]) / (xs[i] - xs[i - 1]) + ys[i - 1];
}

/// NWTC's kernelSmoothing with the triweight kernel.
std::vector<double> smooth(const std::vector<double>& x, const std::vector<double>& f,
                           double radius) {
    std::vector<double> out(f.size(), 0.0);
    for (std::size_t j = 0; j < x.size(); ++j) {
        double sum = 0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double u = std::clamp((x[i] - x[j]) / radius, -1.0, 1.0);
            const double k = 35.0 / 32.0 * std::pow(1 - u * u, 3);
            sum += k;
            out[j] += k * f[i];
        }
        if (sum > 0) out[j] /= sum;
    }
    return out;
}

/// Zero crossings of f(x) by linear interpolation (NWTC's fZeros); with `period`,
/// also between the last and the first point.
std::vector<double> zeros(const std::vector<double>& x, const std::vector<double>& f,
                          double period = 0) {
    std::vector<double> roots;
    auto crosses = [](double a, double b) { return (a < 0 && b >= 0) || (a >= 0 && b < 0); };
    for (std::size_t j = 1; j < f.size(); ++j)
        if (crosses(f[j - 1], f[j]))
            roots.push_back(x[j] - f[j] * (x[j] - x[j - 1]) / (f[j] - f[j - 1]));
    if (period > 0 && !f.empty() && crosses(f.back(), f.front()))
        roots.push_back(x.front() -
                        f.front() * (x.front() - x.back() + period) / (f.front() - f.back()));
    return roots;
}

/// AirfoilInfo's Compute_iLoweriUpper: the first row at or above alphaLower, the last
/// at or below alphaUpper, kept inside the table.
void lower_upper(const std::vector<double>& alpha, const aero::UnsteadyConstants& k, int& lower,
                 int& upper) {
    const int n = size(alpha);
    lower = 0;
    for (int i = 1; i <= n && !lower; ++i)
        if (at(alpha, i) >= k.alphaLower) lower = i;
    upper = 0;
    for (int i = n; i >= 1 && !upper; --i)
        if (at(alpha, i) <= k.alphaUpper) upper = i;
    lower = std::max(1, std::min(n - 1, lower));
    upper = std::max(2, std::min(n, upper));
}

std::vector<double> normal_force(const aero::PolarTable& t, double cd0) {
    std::vector<double> cn(t.alpha.size());
    for (std::size_t i = 0; i < cn.size(); ++i)
        cn[i] = t.cl[i] * std::cos(t.alpha[i]) + (t.cd[i] - cd0) * std::sin(t.alpha[i]);
    return cn;
}

bool on_lift(aero::UnsteadyModel model) {
    return model == aero::UnsteadyModel::hgm || model == aero::UnsteadyModel::oye;
}

/// ComputeUASeparationFunction_zero: f = 0 beyond the attached range, and a fully
/// attached line through +/-180 deg.
void separated_beyond(const std::vector<double>& alpha, const std::vector<double>& c,
                      const aero::UnsteadyConstants& k, SeparationFunction& s) {
    const int n = size(alpha);
    int low = 0, high = 0;
    double low_f = 0, high_f = 0;
    for (int i = 1; i <= n; ++i)
        if (at(alpha, i) < k.alphaLower && (!low || at(s.f, i) <= low_f)) {
            low = i; // the last row of the least f below alphaLower
            low_f = at(s.f, i);
        }
    for (int i = 1; i <= n; ++i)
        if (at(alpha, i) > k.alphaUpper && (!high || at(s.f, i) < high_f)) {
            high = i; // the first row of the least f above alphaUpper
            high_f = at(s.f, i);
        }
    if (!low) low = 1;
    if (!high) high = n;
    const double a_up = at(alpha, high), a_low = at(alpha, low);
    const double c_up = at(s.fully_attached, high), c_low = at(s.fully_attached, low);
    const double rate = (c_up - c_low) / ((a_up - 2 * pi) - a_low);
    for (int i = 1; i <= low; ++i) {
        at(s.fully_attached, i) = (at(alpha, i) - a_low) * rate + c_low;
        at(s.fully_separated, i) = at(c, i);
        at(s.f, i) = 0;
    }
    for (int i = high; i <= n; ++i) {
        at(s.fully_attached, i) = (at(alpha, i) - a_up) * rate + c_up;
        at(s.fully_separated, i) = at(c, i);
        at(s.f, i) = 0;
    }
}

/// ComputeUASeparationFunction_onCl (UA_Mod 4 and 6).
SeparationFunction separation_on_lift(const aero::PolarTable& t, const aero::UnsteadyConstants& k) {
    const int n = size(t.alpha);
    SeparationFunction s{std::vector<double>(t.alpha.size()), t.cl,
                         std::vector<double>(t.alpha.size())};
    if (equal(k.C_lalpha, 0)) {
        separated_beyond(t.alpha, t.cl, k, s);
        return s;
    }
    for (int i = 1; i <= n; ++i) {
        const double a = at(t.alpha, i), cl = at(t.cl, i);
        double f = 1, separated = cl / 2;
        if (!equal(a, k.alpha0)) {
            const double ratio = std::max(0.0, cl / (k.C_lalpha * (a - k.alpha0)));
            f = std::pow(2 * std::sqrt(ratio) - 1, 2);
            if (f < 1) {
                f = std::max(0.0, f);
                separated = (cl - k.C_lalpha * (a - k.alpha0) * f) / (1 - f);
            } else {
                f = 1;
            }
        }
        at(s.f, i) = f;
        at(s.fully_separated, i) = separated;
        at(s.fully_attached, i) = k.C_lalpha * (a - k.alpha0);
    }
    separated_beyond(t.alpha, t.cl, k, s);
    for (int i = 1; i <= n; ++i) {
        const double separated = at(s.fully_separated, i);
        const double inviscid = k.C_lalpha * (at(t.alpha, i) - k.alpha0);
        at(s.f, i) = equal(inviscid, separated)
                         ? 1.0
                         : std::clamp((at(t.cl, i) - separated) / (inviscid - separated), 0.0, 1.0);
    }
    return s;
}

/// ComputeUA360_CnOffset.
double cn_offset(const std::vector<double>& alpha, const std::vector<double>& cn, int row,
                 int lower) {
    const double offset = at(cn, lower) > -0.05 ? at(cn, lower) + 0.05 : 0.0;
    const double scale = 0.1 / deg;
    const double a = at(alpha, row);
    return offset * (std::tanh(scale * (a + pi / 2)) - std::tanh(scale * (a - pi / 2))) / 2;
}

/// ComputeUA360_AttachedFlow, _updateSeparationF and _updateCnSeparated (the Cn-based
/// models); snaps alphaLower and alphaUpper to rows of the table.
SeparationFunction separation_on_normal_force(const aero::PolarTable& t,
                                              const std::vector<double>& cn,
                                              aero::UnsteadyConstants& k) {
    const std::vector<double>& alpha = t.alpha;
    const int n = size(alpha);
    SeparationFunction s{std::vector<double>(alpha.size()), std::vector<double>(alpha.size()),
                         std::vector<double>(alpha.size())};
    int lower = 0, upper = 0;
    lower_upper(alpha, k, lower, upper);
    k.alphaLower = at(alpha, lower);
    k.alphaUpper = at(alpha, upper);

    // Attached flow: the Cn line of the table between lower and upper, and lines to
    // the reverse-flow zero lift near 180 deg (slope -2 pi) outside.
    const double slope_up =
        (at(cn, upper - 1) - at(cn, upper)) / (at(alpha, upper - 1) - at(alpha, upper));
    const double zero_up =
        equal(slope_up, 0) ? at(alpha, upper) : at(alpha, upper) - at(cn, upper) / slope_up;
    const double slope_low =
        (at(cn, lower) - at(cn, lower + 1)) / (at(alpha, lower) - at(alpha, lower + 1));
    const double zero_low =
        equal(slope_low, 0) ? at(alpha, lower) : at(alpha, lower) - at(cn, lower) / slope_low;
    double reverse = at(alpha, 1);
    double largest = -1;
    for (double r : zeros(alpha, cn, 2 * pi))
        if (std::fabs(r) >= 45 * deg && std::fabs(r) > largest) {
            largest = std::fabs(r);
            reverse = r;
        }
    if (largest >= 0 && reverse < -pi / 2) reverse += 2 * pi;
    const double slope_reverse = -2 * pi;
    const double break_up =
        (slope_reverse * reverse - slope_up * zero_up) / (slope_reverse - slope_up);
    const double cn_break_up = slope_up * (break_up - zero_up);
    const double break_low =
        (slope_reverse * (reverse - 2 * pi) - slope_low * zero_low) / (slope_reverse - slope_low);
    const double cn_break_low = slope_low * (break_low - zero_low);
    {
        const double xs[3] = {reverse - 2 * pi, break_low, at(alpha, lower)};
        const double fs[3] = {0, cn_break_low, at(cn, lower)};
        for (int i = 1; i < lower; ++i)
            at(s.fully_attached, i) = interp_extrapolated(at(alpha, i), xs, fs);
    }
    for (int i = lower; i <= upper; ++i) at(s.fully_attached, i) = at(cn, i);
    {
        const double xs[3] = {at(alpha, upper), break_up, reverse};
        const double fs[3] = {at(cn, upper), cn_break_up, 0};
        for (int i = upper + 1; i <= n; ++i)
            at(s.fully_attached, i) = interp_extrapolated(at(alpha, i), xs, fs);
    }

    // The separation function from Kirchhoff's law on Cn.
    for (int i = 1; i <= n; ++i) {
        const double offset = cn_offset(alpha, cn, i, lower);
        double ratio = equal(at(s.fully_attached, i), offset)
                           ? 1.0
                           : (at(cn, i) - offset) / (at(s.fully_attached, i) - offset);
        ratio = std::max(0.25, ratio);
        at(s.f, i) = std::clamp(std::pow(2 * std::sqrt(ratio) - 1, 2), 0.0, 1.0);
    }
    for (int i = lower; i <= upper; ++i) at(s.f, i) = 1;

    // One peak of f near 180 deg, falling monotonically on both sides.
    int shift = 0;
    for (int i = 1; i <= n; ++i)
        if (at(alpha, i) <= break_low) shift = i;
    std::vector<double> a(alpha.size()), f(alpha.size());
    for (int i = 1; i <= n; ++i) {
        const int from = (i - 1 + shift) % n + 1; // Fortran's CSHIFT(x, shift)
        at(a, i) = at(alpha, from);
        at(f, i) = at(s.f, from);
    }
    for (int i = 2; i <= n; ++i)
        if (at(a, i) < at(a, i - 1)) at(a, i) += 2 * pi;
    int peak = 0, upper_break = 0;
    for (int i = 1; i <= n; ++i) {
        if (at(a, i) > break_up && (!peak || at(f, i) > at(f, peak))) peak = i;
        if (at(a, i) >= break_up && (!upper_break || at(a, i) < at(a, upper_break)))
            upper_break = i;
    }
    if (peak && upper_break) {
        for (int i = peak - 1; i >= upper_break + 1 && i >= 2; --i) {
            if (equal(at(f, i), 0)) at(f, i - 1) = 0;
            if (at(f, i - 1) > at(f, i)) at(f, i) = 0.5 * (at(f, i + 1) + at(f, i - 1));
        }
        for (int i = std::max(peak + 1, 2); i <= n - 1; ++i) {
            if (equal(at(f, i), 0)) at(f, i + 1) = 0;
            if (at(f, i + 1) > at(f, i)) at(f, i) = 0.5 * (at(f, i + 1) + at(f, i - 1));
        }
    }
    for (int i = 1; i <= n; ++i) at(s.f, (i - 1 + shift) % n + 1) = at(f, i);

    // Fully separated Cn.
    for (int i = 1; i <= n; ++i)
        at(s.fully_separated, i) =
            equal(at(s.f, i), 1)
                ? 0.5 * (at(cn, i) + cn_offset(alpha, cn, i, lower))
                : (at(cn, i) - at(s.fully_attached, i) * at(s.f, i)) / (1 - at(s.f, i));
    return s;
}

/// alpha1 or alpha2: where f crosses 0.7, the crossing nearest a first guess.
double crossing(const std::vector<double>& alpha, const std::vector<double>& f, int from, int to,
                int guess) {
    std::vector<double> x, g;
    for (int i = from; i <= to; ++i) {
        x.push_back(at(alpha, i));
        g.push_back(0.7 - at(f, i));
    }
    const std::vector<double> roots = zeros(x, g);
    if (roots.empty()) return at(alpha, guess);
    double best = roots.front();
    for (double r : roots)
        if (std::fabs(r - at(alpha, guess)) < std::fabs(best - at(alpha, guess))) best = r;
    return roots.size() == 1 ? roots.front() : best;
}

/// A value given in degrees, in radians; `fallback` when not given.
double radians(const std::optional<double>& v, double fallback) {
    return v ? *v * deg : fallback;
}
double value(const std::optional<double>& v, double fallback) {
    return v ? *v : fallback;
}

} // namespace

bool constant_polar(const aero::PolarTable& t) {
    if (t.alpha.size() < 3) return true;
    for (const std::vector<double>* c : {&t.cl, &t.cd, &t.cm})
        for (std::size_t i = 0; i + 1 < c->size(); ++i)
            if (!equal((*c)[i], (*c)[i + 1])) return false;
    return true;
}

SeparationFunction separation_function(const aero::PolarTable& t, aero::UnsteadyConstants& k,
                                       aero::UnsteadyModel model) {
    if (on_lift(model)) return separation_on_lift(t, k);
    return separation_on_normal_force(t, normal_force(t, k.Cd0), k);
}

aero::UnsteadyConstants unsteady_constants(const aero::PolarTable& t,
                                           const aerodyn::UnsteadyEntries& e,
                                           aero::UnsteadyModel model) {
    aero::UnsteadyConstants k;
    k.eta_e = value(e.eta_e, 1);
    k.k0 = value(e.k0, 0);
    k.k1 = value(e.k1, 0);
    k.k2 = value(e.k2, 0);
    k.k3 = value(e.k3, 0);
    k.k1_hat = value(e.k1_hat, 0);
    k.S1 = value(e.S1, 0);
    k.S2 = value(e.S2, 0);
    k.S3 = value(e.S3, 0);
    k.S4 = value(e.S4, 0);
    k.T_f0 = value(e.T_f0, 3);
    k.T_V0 = value(e.T_V0, 6);
    k.T_p = value(e.T_p, 1.7);
    k.T_VL = value(e.T_VL, 11);
    k.b1 = value(e.b1, 0.14);
    k.b2 = value(e.b2, 0.53);
    k.b5 = value(e.b5, 5);
    k.A1 = value(e.A1, 0.3);
    k.A2 = value(e.A2, 0.7);
    k.A5 = value(e.A5, 1);
    k.x_cp_bar = value(e.x_cp_bar, 0.2);
    k.filtCutOff = value(e.filtCutOff, 0.5);
    k.St_sh = value(e.St_sh, 0.19);
    k.UACutout = radians(e.UACutout, 45 * deg);
    k.alpha0 = radians(e.alpha0, 0);
    k.alpha1 = radians(e.alpha1, 0);
    k.alpha2 = radians(e.alpha2, 0);
    k.alphaUpper = radians(e.alphaUpper, 0);
    k.alphaLower = radians(e.alphaLower, 0);
    k.C_nalpha = value(e.C_nalpha, 0);
    k.C_lalpha = value(e.C_lalpha, 0);
    k.Cn1 = value(e.Cn1, 0);
    k.Cn2 = value(e.Cn2, 0);
    k.Cd0 = value(e.Cd0, 0);
    k.Cm0 = value(e.Cm0, 0);

    const std::vector<double>& alpha = t.alpha;
    const int n = size(alpha);
    const double limit = 20 * deg; // the range of the attached-flow estimates
    int cd_min = 0;                // the least drag within the range (first of equals)
    double cd_high = -HUGE_VAL, cl_high = -HUGE_VAL;
    for (int i = 1; i <= n; ++i) {
        if (std::fabs(at(alpha, i)) > limit) continue;
        if (!cd_min || at(t.cd, i) < at(t.cd, cd_min)) cd_min = i;
        cd_high = std::max(cd_high, at(t.cd, i));
        cl_high = std::max(cl_high, at(t.cl, i));
    }
    const double cd_low = cd_min ? at(t.cd, cd_min) : 0;
    if (!cd_min || cd_high == cd_low || cl_high < 0.01) {
        // A cylinder, or no row within +/-20 deg: fixed estimates.
        if (!e.Cd0) k.Cd0 = cd_min ? at(t.cd, cd_min) : t.cd.front();
        if (!e.alpha0) k.alpha0 = 0;
        if (!e.C_nalpha) k.C_nalpha = 0;
        if (!e.C_lalpha) k.C_lalpha = 0;
        if (!e.Cm0) k.Cm0 = 0;
        if (!e.alpha1) k.alpha1 = 10 * deg;
        if (!e.alpha2) k.alpha2 = -10 * deg;
        if (!e.Cn1) k.Cn1 = 0;
        if (!e.Cn2) k.Cn2 = 0;
        if (!e.alphaLower) k.alphaLower = -5 * deg;
        if (!e.alphaUpper) k.alphaUpper = 5 * deg;
        separation_function(t, k, model);
        return k;
    }

    const double alpha_cd_min = at(alpha, cd_min);
    if (!e.Cd0) k.Cd0 = at(t.cd, cd_min);
    const std::vector<double> cn = normal_force(t, k.Cd0);
    std::vector<double> mid(alpha.size() - 1), cn_slope(mid.size()), cl_slope(mid.size());
    for (int i = 1; i <= n - 1; ++i) {
        const double da = at(alpha, i + 1) - at(alpha, i);
        at(cn_slope, i) = (at(cn, i + 1) - at(cn, i)) / da;
        at(cl_slope, i) = (at(t.cl, i + 1) - at(t.cl, i)) / da;
        at(mid, i) = 0.5 * (at(alpha, i + 1) + at(alpha, i));
    }
    cn_slope = smooth(mid, cn_slope, 2 * deg);
    const int m = n - 1;
    const double slope_at_cd_min = interp_clamped(alpha_cd_min, mid, cn_slope);

    int high_limit = 0, low_limit = 0;
    for (int i = 1; i <= m; ++i)
        if (at(mid, i) < limit) high_limit = i;
    for (int i = m; i >= 1; --i)
        if (at(mid, i) > -limit) low_limit = i;
    high_limit = std::min(high_limit + 1, m);
    low_limit = std::max(low_limit - 1, 1);
    if (high_limit - low_limit < 3) high_limit = std::min(low_limit + 2, m);
    if (high_limit - low_limit < 3) low_limit = std::max(high_limit - 2, 1);

    // alphaUpper and alphaLower: where the smoothed Cn slope falls below 90 % of its
    // largest value, going up and down from the least drag.
    int high2 = high_limit;
    if (!e.alphaUpper) {
        int high = high_limit < cd_min ? m : high_limit;
        double peak = slope_at_cd_min;
        high2 = cd_min;
        for (int i = cd_min; i <= high; ++i) {
            high2 = i;
            if (at(cn_slope, i) > peak)
                peak = at(cn_slope, i);
            else if (at(cn_slope, i) < 0.9 * peak)
                break;
        }
        if (high2 == cd_min) {
            k.alphaUpper = alpha_cd_min;
        } else {
            high2 = std::min(std::max(1, high2 - 1), m);
            k.alphaUpper = at(mid, high2);
        }
    }
    if (!e.alphaLower) {
        double peak = slope_at_cd_min;
        int low = low_limit;
        const int high = std::max(1, std::min({high2, cd_min, m}));
        if (high < low) low = 1;
        int low2 = high;
        for (int i = high; i >= low; --i) {
            low2 = i;
            if (at(cn_slope, i) > peak)
                peak = at(cn_slope, i);
            else if (at(cn_slope, i) < 0.9 * peak)
                break;
        }
        if (low2 == cd_min) {
            k.alphaLower = alpha_cd_min;
        } else {
            low2 = std::min(std::max(1, low2 + 1), m);
            k.alphaLower = at(mid, low2);
        }
    }

    // C_nalpha, C_lalpha and alpha0: least squares on the rows inside the attached
    // range, a fifth of it off each end.
    if (!e.C_nalpha || !e.C_lalpha || !e.alpha0) {
        const double margin = 0.2 * (k.alphaUpper - k.alphaLower);
        int lo = low_limit;
        while (lo < high_limit - 1 && at(alpha, lo) < k.alphaLower + margin) ++lo;
        int hi = high_limit;
        while (hi > lo + 1 && at(alpha, hi) > k.alphaUpper - margin) --hi;
        double xm = 0, cnm = 0, clm = 0;
        const int count = hi - lo + 1;
        for (int i = lo; i <= hi; ++i) {
            xm += at(alpha, i) / count;
            cnm += at(cn, i) / count;
            clm += at(t.cl, i) / count;
        }
        double sxx = 0, sxn = 0, sxl = 0;
        for (int i = lo; i <= hi; ++i) {
            const double dx = at(alpha, i) - xm;
            sxx += dx * dx;
            sxn += dx * (at(cn, i) - cnm);
            sxl += dx * (at(t.cl, i) - clm);
        }
        const double cn_alpha = sxx > 0 ? sxn / sxx : 0;
        const double cl_alpha = sxx > 0 ? sxl / sxx : 0;
        const double cn_zero = cnm - cn_alpha * xm;
        if (!e.C_nalpha) k.C_nalpha = cn_alpha;
        if (!e.C_lalpha) k.C_lalpha = cl_alpha;
        if (!e.alpha0) k.alpha0 = equal(cn_alpha, 0) ? 0 : -cn_zero / cn_alpha;
    }
    if (!e.Cm0) k.Cm0 = t.cm.empty() ? 0 : interp_clamped(k.alpha0, alpha, t.cm);

    const SeparationFunction s = separation_function(t, k, model);
    int lower = 0, upper = 0;
    lower_upper(alpha, k, lower, upper);
    if (!e.alpha1) {
        int guess = 0;
        for (int i = 1; i <= n && !guess; ++i)
            if (at(alpha, i) >= k.alphaUpper && at(s.f, i) <= 0.7) guess = i;
        k.alpha1 = crossing(alpha, s.f, upper, n, std::max(1, guess));
    }
    if (!e.alpha2) {
        int guess = 0;
        for (int i = 1; i <= n; ++i)
            if (at(alpha, i) <= k.alphaLower && at(s.f, i) <= 0.7) guess = i;
        k.alpha2 = crossing(alpha, s.f, 1, lower, std::max(1, guess));
    }
    if (!e.Cn1) k.Cn1 = interp_clamped(k.alpha1, alpha, cn);
    if (!e.Cn2) k.Cn2 = interp_clamped(k.alpha2, alpha, cn);
    return k;
}

aero::Airfoil to_airfoil(const aerodyn::AirfoilFile& file, aero::UnsteadyModel model) {
    aero::Airfoil out;
    out.name = std::filesystem::path(file.file->path()).filename().string();
    out.interpolation = file.interp_order.value_or(1) == 3 ? aero::Interpolation::cubic_spline
                                                           : aero::Interpolation::linear;
    out.non_dimensional_area = file.non_dimensional_area;
    for (const aerodyn::AirfoilTable& t : file.tables) {
        aero::PolarTable p;
        p.reynolds = t.reynolds;
        p.user_prop = t.user_prop;
        for (double a : t.alpha) p.alpha.push_back(a * deg);
        p.cl = t.cl;
        p.cd = t.cd;
        p.cm = t.cm;
        if (!constant_polar(p))
            p.unsteady = unsteady_constants(
                p, t.has_unsteady ? t.unsteady : aerodyn::UnsteadyEntries{}, model);
        out.tables.push_back(std::move(p));
    }
    return out;
}

} // namespace yamsc::aerodyn_input
