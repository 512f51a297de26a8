#include "yamsc/aero/bem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "yamsc/aero/polar.hpp"

namespace yamsc::aero {

namespace {

constexpr double pi = 3.14159265358979323846;
// AeroDyn's margin around the singular inflow angles 0 and +-pi/2:
// 10 sqrt(machine epsilon) in double precision.
const double phi_margin = 10.0 * std::sqrt(std::numeric_limits<double>::epsilon());
constexpr double induction_limit = 1e6;

// NWTC's EqualRealNos: equal to 50 machine epsilons, relative above 1.
bool nearly_equal(double x, double y) {
    const double scale = std::max(std::abs(x + y), 1.0);
    return std::abs(x - y) <= scale * 50.0 * std::numeric_limits<double>::epsilon();
}

// Below 1 mm/s a velocity counts as zero for the BEM (AeroDyn's VelocityIsZero).
bool velocity_is_zero(double v) {
    return std::abs(v) < 0.001;
}

double loss_constant_tip(const ElementInput& in) {
    return in.blades * (in.z_tip - in.z) / (2.0 * in.z);
}
double loss_constant_hub(const ElementInput& in) {
    return in.blades * (in.z - in.z_hub) / (2.0 * in.z_hub);
}

// At the tip (or the hub) with its loss on, AeroDyn fixes a = 1, a' = 0.
bool fixed_inductions(double c_tip, double c_hub, const BemOptions& opt) {
    return (opt.tip_loss && nearly_equal(c_tip, 0.0)) || (opt.hub_loss && nearly_equal(c_hub, 0.0));
}

// Below exp(-37) < 1e-16, acos returns acos(0)'s double (pi/2 - x rounds to it
// for x below 1.7e-16): the factor far from the tip or the hub, and at the
// regions' ends (sin phi about 1e-7), without its exponential and arc cosine.
constexpr double negligible_exponent = -37.0;
const double prandtl_far = 2.0 / pi * std::acos(0.0);

double prandtl(double constant, double abs_sin_phi) {
    const double x = -constant / abs_sin_phi;
    if (x < negligible_exponent) return prandtl_far;
    return 2.0 / pi * std::acos(std::min(1.0, std::exp(x)));
}

double sign_of(double magnitude, double s) {
    return s >= 0 ? magnitude : -magnitude;
}

// The wake-free inflow angle, or phi with the given inductions.
double inflow_angle(double vx, double vy, double a, double ap) {
    const double x = vx * (1.0 - a);
    const double y = vy * (1.0 + ap);
    if (nearly_equal(x, 0.0) && nearly_equal(y, 0.0)) return 0.0;
    return std::atan2(x, y);
}

// Brent's method on [lo, hi] with f(lo), f(hi) of opposite signs: stops when the
// bracket is below x_tolerance (AeroDyn's sub_brent: opt.angle_tolerance) or |f|
// below opt.tolerance.
// `at_b`: the residual at the returned root, when the search evaluated it there;
// `slope`: df/dphi by the last two points (a warm bracket's next step).
struct BrentResult {
    double x;
    bool valid;
    const Residual* at_b;
    double slope;
};

double secant_slope(double x0, double f0, double x1, double f1) {
    return x1 != x0 ? (f1 - f0) / (x1 - x0) : 0.0;
}

BrentResult brent(const ElementTerms& el, double lo, double hi, double flo, double fhi,
                  bool hi_valid, Residual& rb, double x_tolerance) {
    const BemOptions& opt = el.opt;
    const double eps = std::numeric_limits<double>::epsilon();
    double a = lo, b = hi, fa = flo, fb = fhi;
    double c = a, fc = fa, d = b - a, e = d;
    bool valid = hi_valid;
    bool b_known = false; // rb holds the residual at b
    for (int iter = 1; iter <= opt.max_iterations; ++iter) {
        if (iter == 1 || (fb > 0 && fc > 0) || (fb <= 0 && fc <= 0)) {
            c = a;
            fc = fa;
            e = b - a;
            d = e;
        }
        if (std::abs(fc) < std::abs(fb)) {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
            b_known = false;
        }
        const double tol = 2.0 * eps * std::abs(b) + x_tolerance;
        const double m = 0.5 * (c - b);
        if (std::abs(m) <= tol || fb == 0.0)
            return {b, valid, b_known ? &rb : nullptr, secant_slope(b, fb, c, fc)};
        if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
            double s = fb / fa, p, q;
            if (a != c) {
                const double qa = fa / fc, r = fb / fc;
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            } else {
                p = 2.0 * m * s;
                q = 1.0 - s;
            }
            if (p <= 0) {
                p = -p;
            } else {
                q = -q;
            }
            s = e;
            e = d;
            if (2.0 * p >= 3.0 * m * q - std::abs(tol * q) || p >= std::abs(0.5 * s * q)) {
                e = m;
                d = m;
            } else {
                d = p / q;
            }
        } else {
            e = m;
            d = m;
        }
        a = b;
        fa = fb;
        b += std::abs(d) <= tol ? (m > 0 ? tol : -tol) : d;
        rb = bem_residual(el, b);
        b_known = true;
        fb = rb.f;
        valid = rb.valid;
        if (std::abs(fb) < opt.tolerance) return {b, valid, &rb, secant_slope(a, fa, b, fb)};
    }
    return {b, valid, b_known ? &rb : nullptr, secant_slope(a, fa, b, fb)};
}

// The root and, when the search evaluated it there, the residual at it (the
// same numbers bem_residual gives again).
struct SolvedPhi {
    double phi;
    bool valid;
    const Residual* residual = nullptr;
};

// The momentum region's ends for inflow along vx's sign: the one near phi = 0
// and the one near +-pi/2.
struct Region {
    double near, far;
};
Region momentum_region(double vx) {
    const double s = vx > 0 ? 1.0 : -1.0;
    return {s * phi_margin, s * (pi / 2 - phi_margin)};
}

bool strictly_between(double x, double a, double b) {
    return (a < x && x < b) || (b < x && x < a);
}

void remember_slope(BracketMemory& memory, double slope) {
    if (std::isfinite(slope) && slope != 0.0) memory.slope = slope;
}

// The warm bracket: AeroDyn's search would find the momentum region's ends of
// opposite signs (the memory's) and narrow its bracket to the side of the guess
// where the near end's sign differs from f(guess)'s or not. The root is sought
// on that side only, between the guess and a point a guessed step away (then
// four times as far): a sign change there is a root in the bracket AeroDyn's
// Brent would search. Brent solves in it, called as AeroDyn calls it (the
// guess the upper end when the root lies towards the near end). Returns false
// when it finds no valid root: the full search then decides.
bool warm_bracket(const ElementTerms& el, double guess, double f_guess, BracketMemory& memory,
                  Residual (&scratch)[4], SolvedPhi& out) {
    if (!memory.ends_known || memory.slope == 0.0) return false;
    const Region region = momentum_region(el.in.vx);
    if (!strictly_between(guess, region.near, region.far)) return false;
    const bool towards_near = (f_guess >= 0) != memory.near_end_nonnegative;
    const double end = towards_near ? region.near : region.far;
    const double room = std::abs(end - guess), direction = end > guess ? 1.0 : -1.0;
    const double step = 1.5 * std::abs(f_guess / memory.slope) + el.opt.angle_tolerance;
    double inner = guess, f_inner = f_guess;
    bool inner_valid = true;
    for (const double factor : {1.0, 4.0}) {
        if (factor * step >= room) return false;
        const double probe = guess + direction * factor * step;
        const Residual& r = scratch[1] = bem_residual(el, probe);
        if ((r.f >= 0) == (f_guess >= 0)) {
            inner = probe;
            f_inner = r.f;
            inner_valid = r.valid;
            continue;
        }
        // A warm bracket starts a few micro-radians wide, where AeroDyn's angle
        // tolerance would end the search at once, anywhere in it: only |f| below
        // opt.tolerance ends it, as it ends AeroDyn's wide searches, so that the
        // root does not depend on the history that placed the bracket.
        const double x_tolerance = 0.0;
        const BrentResult root =
            towards_near
                ? brent(el, probe, inner, r.f, f_inner, inner_valid, scratch[3], x_tolerance)
                : brent(el, inner, probe, f_inner, r.f, r.valid, scratch[3], x_tolerance);
        if (!root.valid) return false;
        remember_slope(memory, root.slope);
        out = {root.x, true, root.at_b};
        return true;
    }
    return false;
}

// AeroDyn's BEMT_UnCoupledSolve: the guess if it is still a root, else the
// three regions in AeroDyn's order, the first bracketed valid root. With a
// memory, the warm bracket before the regions.
SolvedPhi solve_phi(const ElementTerms& el, Residual (&scratch)[4], BracketMemory* memory) {
    const ElementInput& in = el.in;
    const BemOptions& opt = el.opt;
    if (velocity_is_zero(in.vx)) return {0.0, true};
    if (velocity_is_zero(in.vy)) return {in.vx > 0 ? pi / 2 : -pi / 2, true};

    const double guess = in.phi_guess;
    bool guess_is_valid = false;
    double f_guess = 0;
    if (in.guess_valid && !nearly_equal(guess, 0.0) && !nearly_equal(std::abs(guess), pi / 2)) {
        const Residual& r = scratch[0] = bem_residual(el, guess);
        if (std::abs(r.f) < opt.tolerance && r.valid) return {guess, true, &r};
        guess_is_valid = r.valid;
        f_guess = r.f;
        SolvedPhi warm;
        if (memory && guess_is_valid && warm_bracket(el, guess, f_guess, *memory, scratch, warm))
            return warm;
    }
    if (memory) memory->ends_known = false; // until region 0's Brent finds a valid root

    // Regions: the momentum region first, then the two others in the order the
    // previous phi suggests.
    double lower[3], upper[3];
    const bool near_zero = guess < pi / 4 && guess > -pi / 4;
    const double s = in.vx > 0 ? 1.0 : -1.0;
    const Region momentum = momentum_region(in.vx);
    lower[0] = momentum.near;
    upper[0] = momentum.far;
    const int second = near_zero ? 1 : 2, third = near_zero ? 2 : 1;
    lower[second] = -s * pi / 4;
    upper[second] = -s * phi_margin;
    lower[third] = s * (pi / 2 + phi_margin);
    upper[third] = s * (pi - phi_margin);

    for (int i = 0; i < 3; ++i) {
        double lo = lower[i], hi = upper[i];
        const Residual& r1 = scratch[1] = bem_residual(el, lo);
        const Residual& r2 = scratch[2] = bem_residual(el, hi);
        double f1 = r1.f, f2 = r2.f;
        bool hi_valid = r2.valid;
        if (nearly_equal(f1, 0.0) && nearly_equal(f2, 0.0) && r1.valid && r2.valid)
            return {lo > 0 ? lo : hi, true,
                    lo > 0 ? &r1 : &r2}; // every phi is a root: the one nearer 0
        if (std::abs(f1) < opt.tolerance) {
            if (std::abs(f2) < std::abs(f1) && r2.valid) return {hi, true, &r2};
            if (r1.valid) return {lo, true, &r1};
        } else if (std::abs(f2) < opt.tolerance && r2.valid) {
            return {hi, true, &r2};
        }
        if ((f1 >= 0) == (f2 >= 0)) continue; // no sign change in this region
        const bool near_nonnegative = f1 >= 0;
        if (guess_is_valid && ((lo < guess && guess < hi) || (hi < guess && guess < lo))) {
            // Narrow the bracket with the previous solution.
            if ((f1 >= 0) != (f_guess >= 0)) {
                hi = guess;
                f2 = f_guess;
                hi_valid = true;
            } else {
                lo = guess;
                f1 = f_guess;
            }
        }
        const BrentResult root =
            brent(el, lo, hi, f1, f2, hi_valid, scratch[3], opt.angle_tolerance);
        if (root.valid) {
            if (memory && i == 0) {
                memory->ends_known = true;
                memory->near_end_nonnegative = near_nonnegative;
                remember_slope(*memory, root.slope);
            }
            return {root.x, true, root.at_b};
        }
        guess_is_valid = false; // AeroDyn carries Brent's last validity on
    }
    return {inflow_angle(in.vx, in.vy, 0.0, 0.0), false};
}

} // namespace

BemOptions bem_options(const RotorInput& input) {
    BemOptions o;
    o.tip_loss = input.tip_loss;
    o.hub_loss = input.hub_loss;
    o.tangential_induction = input.tangential_induction;
    o.axial_drag = input.axial_drag;
    o.tangential_drag = input.tangential_drag;
    if (input.induction_tolerance > 0) o.tolerance = input.induction_tolerance;
    if (input.inflow_angle_tolerance > 0) o.angle_tolerance = input.inflow_angle_tolerance;
    o.max_iterations = input.max_iterations;
    o.skew_redistribution = input.skew == SkewModel::active &&
                            input.skew_redistribution == SkewRedistribution::pitt_peters;
    o.skew_factor = input.skew_redistribution_factor;
    o.use_pitching_moment = input.use_pitching_moment;
    return o;
}

namespace {

// Prandtl's loss at |sin phi| = s for the loss constants c_tip, c_hub.
double prandtl_at(double c_tip, double c_hub, const BemOptions& opt, double s) {
    if (nearly_equal(s, 0.0)) return 1.0;
    double F = 1.0;
    if (opt.tip_loss) F *= prandtl(c_tip, s);
    if (opt.hub_loss) F *= prandtl(c_hub, s);
    return F;
}

} // namespace

double prandtl_loss(const ElementInput& in, const BemOptions& opt, double phi) {
    return prandtl_at(loss_constant_tip(in), loss_constant_hub(in), opt, std::abs(std::sin(phi)));
}

double axial_induction_momentum(double k, double F) {
    if (k <= 2.0 / 3.0)
        return nearly_equal(k, -1.0) ? -sign_of(induction_limit, 1.0 + k) : k / (1.0 + k);
    // Buhl: CT = 8/9 + (4F - 40/9) a + (50/9 - 4F) a^2 equated to 4 F k (1 - a)^2.
    const double t = 2.0 * F * k;
    const double g1 = t - (10.0 / 9.0 - F);
    const double g2 = t - (4.0 / 3.0 - F) * F;
    const double g3 = t - (25.0 / 9.0 - 2.0 * F);
    if (std::abs(g3) < 1e-6) return 1.0 - 0.5 / std::sqrt(g2);
    return (g1 - std::sqrt(std::abs(g2))) / g3;
}

double induction_weight(double tsr) {
    constexpr double lower = 1.0, upper = 2.0;
    const double x = std::abs(tsr);
    if (x >= upper) return 1.0;
    if (x <= lower) return 0.0;
    return 0.5 * (1.0 - std::cos(pi * (x - lower) / (upper - lower)));
}

ElementTerms::ElementTerms(const ElementInput& in, const BemOptions& opt)
    : in(in), opt(opt), c_tip(loss_constant_tip(in)), c_hub(loss_constant_hub(in)),
      fixed(fixed_inductions(c_tip, c_hub, opt)),
      no_inflow(velocity_is_zero(in.vx) || velocity_is_zero(in.vy)),
      sigma(in.blades * in.chord / (2.0 * pi * in.r)), lambda(in.vy / in.vx) {}

Residual bem_residual(const ElementInput& in, const BemOptions& opt, double phi) {
    return bem_residual(ElementTerms(in, opt), phi);
}

Residual bem_residual(const ElementTerms& e, double phi) {
    const ElementInput& in = e.in;
    const BemOptions& opt = e.opt;
    Residual r;
    if (e.fixed) {
        r.a = 1.0;
        return r;
    }
    if (nearly_equal(phi, 0.0) || e.no_inflow) return r;

    const Coefficients c = coefficients(in, phi - in.theta);
    const double sphi = std::sin(phi), cphi = std::cos(phi);
    const double cx = c.cl * cphi + (opt.axial_drag ? c.cd * sphi : 0.0);
    const double cy = c.cl * sphi - (opt.tangential_drag ? c.cd * cphi : 0.0);
    const double F = std::max(prandtl_at(e.c_tip, e.c_hub, opt, std::abs(sphi)), 1e-4);
    r.F = F;

    const double sigma = e.sigma;
    const double k = sigma * cx / (4.0 * F * sphi * sphi);
    r.k = k;
    const bool momentum = (phi > 0 && in.vx >= 0) || (phi < 0 && in.vx < 0);
    double a;
    if (momentum) {
        a = axial_induction_momentum(k, F);
        if (k < -1.0) r.valid = false; // a > 1 is no momentum solution
    } else {                           // propeller brake
        if (nearly_equal(k, 1.0)) {
            r.valid = false;
            a = induction_limit;
        } else {
            a = k / (k - 1.0);
        }
        if (k <= 1.0) r.valid = false; // a < 1 is no brake solution
    }

    double ap = 0, kp = 0;
    if (opt.tangential_induction) {
        if (nearly_equal(cphi, 0.0)) {
            ap = -1.0;
            kp = sign_of(induction_limit, cy * sphi) * (in.vx >= 0 ? 1.0 : -1.0);
        } else {
            kp = sigma * cy / (4.0 * F * sphi * cphi);
            if (in.vx < 0) kp = -kp;
            ap = nearly_equal(kp, 1.0) ? sign_of(induction_limit, 1.0 - kp) : kp / (1.0 - kp);
        }
    }

    const double lambda = e.lambda;
    if (momentum) {
        r.f = nearly_equal(a, 1.0) ? -cphi / lambda * (1.0 - kp)
                                   : sphi / (1.0 - a) - cphi / lambda * (1.0 - kp);
    } else {
        r.f = sphi * (1.0 - k) - cphi / lambda * (1.0 - kp);
    }
    r.a = a;
    r.ap = ap;
    r.kp = kp;
    return r;
}

namespace {

ElementSolution inductions(const ElementInput& in, const BemOptions& opt, BracketMemory* memory) {
    ElementSolution s;
    Residual scratch[4];
    const ElementTerms terms(in, opt);
    const SolvedPhi solved = solve_phi(terms, scratch, memory);
    s.phi_bem = solved.phi;
    s.valid = solved.valid;

    double a = 0, ap = 0;
    if (solved.valid) {
        const Residual r = solved.residual ? *solved.residual : bem_residual(terms, solved.phi);
        s.F = r.F;
        if (r.valid) {
            a = std::clamp(r.a, -1.0, 1.5);
            ap = std::clamp(r.ap, -1.0, 1.0);
        }
    }
    s.a_bem = a;
    s.ap_bem = ap;
    return s;
}

} // namespace

ElementSolution solve_inductions(const ElementInput& in, const BemOptions& opt) {
    return inductions(in, opt, nullptr);
}

ElementSolution solve_inductions(const ElementInput& in, const BemOptions& opt,
                                 BracketMemory& memory) {
    return inductions(in, opt, &memory);
}

void finish_element(const ElementInput& in, const BemOptions& opt, double rho, ElementSolution& s) {
    double a = s.a_bem, ap = s.ap_bem;
    // Pitt/Peters: more induction on the downwind side of the skewed wake. At a
    // fixed-induction node (tip or hub) AeroDyn leaves a = 1.
    if (opt.skew_redistribution &&
        !fixed_inductions(loss_constant_tip(in), loss_constant_hub(in), opt)) {
        double chi = (0.6 * a + 1.0) * in.chi0;
        chi = std::remainder(chi, 2.0 * pi);
        const double t = std::abs(chi) > pi / 2 ? (chi >= 0 ? 1.0 : -1.0) : std::tan(chi / 2.0);
        a *= 1.0 + opt.skew_factor * t * in.tip_ratio * std::sin(in.psi);
    }
    a *= in.weight;
    ap *= in.weight;
    element_loads(in, opt, rho, a, ap, s);
}

ElementSolution solve_element(const ElementInput& in, const BemOptions& opt, double rho) {
    ElementSolution s = solve_inductions(in, opt);
    finish_element(in, opt, rho, s);
    return s;
}

void element_loads(const ElementInput& in, const BemOptions& opt, double rho, double a, double ap,
                   ElementSolution& s) {
    s.a = a;
    s.ap = ap;
    s.phi = inflow_angle(in.vx, in.vy, a, ap);
    s.alpha = s.phi - in.theta;
    const double wx = in.vx * (1.0 - a), wy = in.vy * (1.0 + ap);
    s.vrel = std::sqrt(wx * wx + wy * wy);
    set_coefficients(s, lookup(*in.airfoil, s.alpha), in.chord, rho, opt);
}

void set_coefficients(ElementSolution& s, const Coefficients& c, double chord, double rho,
                      const BemOptions& opt) {
    s.cl = c.cl;
    s.cd = c.cd;
    s.cm = opt.use_pitching_moment ? c.cm : 0.0;
    const double cphi = std::cos(s.phi), sphi = std::sin(s.phi);
    s.cx = c.cl * cphi + c.cd * sphi;
    s.cy = c.cl * sphi - c.cd * cphi;
    const double qc = 0.5 * rho * s.vrel * s.vrel * chord;
    s.fx = s.cx * qc;
    s.fy = s.cy * qc;
    s.mz = s.cm * qc * chord;
}

} // namespace yamsc::aero
