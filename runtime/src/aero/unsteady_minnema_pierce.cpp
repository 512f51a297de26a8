// UA_Mod 3: Beddoes-Leishman after Minnema/Pierce, with FLookup (the separation
// functions from the steady polar), as UnsteadyAero's ComputeKelvinChain,
// UA_CalcOutput and UA_UpdateDiscOtherState compute it.
#include "unsteady_math.hpp"
#include "yamsc/aero/unsteady_airfoil.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yamsc::aero {

using unsteady_detail::blend_steady;
using unsteady_detail::fixed;
using unsteady_detail::near;
using unsteady_detail::pi;
using unsteady_detail::wrap_pi;

namespace {

constexpr double gonzalez_factor = 0.2; // offset of sqrt(f_c) (FLookup)

// Y_n = Y_{n-1} exp(-dt/T) + (x_n - x_{n-1}) exp(-dt/(2T)).
// (One exponential: the chain evaluates a dozen of these per step.)
double deficiency(double dt, double T, double y_prev, double x, double x_prev) {
    const double half = std::exp(-0.5 * dt / T);
    return y_prev * half * half + (x - x_prev) * half;
}

double square(double x) {
    return x * x;
}

bool same_single(double a, double b) {
    return static_cast<float>(a) == static_cast<float>(b);
}

struct Separation {
    double f = 1;
    double cn_fs = 0;
};

// The steady polar at an angle, with its sine and cosine: the two separation functions
// of alpha_f read the same point.
struct PolarAt {
    double alpha, sin, cos;
    UnsteadyAirfoil::Point p;
};

PolarAt polar_at(const UnsteadyAirfoil& af, double alpha) {
    return {alpha, std::sin(alpha), std::cos(alpha), af.at(alpha)};
}

// f solving Cn = C_nalpha_circ (alpha - alpha0) ((1 + sqrt f)/2)^2 at the polar's Cn, and
// the fully separated Cn (Get_f_from_Lookup).
Separation f_from_lookup(const UnsteadyAirfoil& af, const PolarAt& at, double alpha0,
                         double cna_circ) {
    const double alpha = near(alpha0, at.alpha);
    const double da = alpha - alpha0;
    const double cn = at.p.cl * at.cos + (at.p.cd - af.constants().Cd0) * at.sin;
    double root = 0;
    if (!same_single(cna_circ, 0) && !same_single(alpha, alpha0) && !same_single(cn, 0))
        root = std::max(0.0, cn / (cna_circ * da));
    Separation s;
    s.f = std::min(1.0, square(2 * std::sqrt(root) - 1));
    s.cn_fs = s.f == 1 ? 0.0 : (cn - cna_circ * da * s.f) / (1 - s.f);
    return s;
}

// The chordwise separation function (Get_f_c_from_Lookup), limited to (1 + 0.2)^2.
double f_c_from_lookup(const UnsteadyAirfoil& af, const PolarAt& at, double alpha0_in,
                       double cna_circ, double eta_e) {
    constexpr double limit = (1 + gonzalez_factor) * (1 + gonzalez_factor);
    double alpha = wrap_pi(at.alpha);
    const double alpha0 = wrap_pi(alpha0_in);
    if (same_single(alpha, 0) || same_single(alpha, alpha0) || same_single(cna_circ, 0))
        return limit;
    const double cc = at.p.cl * at.sin - (at.p.cd - af.constants().Cd0) * at.cos;
    alpha = near(alpha0, alpha);
    const double denom = eta_e * cna_circ * (alpha - alpha0) * (at.sin / at.cos);
    return std::min(limit, square(cc / denom + gonzalez_factor));
}

using Chain = MinnemaPierceChain;

// Written in place (the memo's entry): no copy of the chain.
void kelvin_chain(const UnsteadyAirfoil& af, const UnsteadySettings& s, double c, double dt,
                  const UnsteadyInput& u, const MinnemaPierceState& x, Chain& kc) {
    const UnsteadyConstants& k = af.constants();
    const double eta_e = s.f_lookup ? 1.0 : k.eta_e;
    kc = Chain{};
    const double M = u.U / s.speed_of_sound;
    if (std::abs(M) >= 1)
        throw std::domain_error("unsteady aerodynamics: Mach number of 1 or more");
    const double beta2 = 1 - M * M, beta = std::sqrt(beta2);
    kc.cna_circ = k.C_nalpha / beta;
    kc.ds = 2 * u.U * dt / c;

    const double alpha_filt_prev = x.first_pass ? u.alpha : x.alpha_filt;
    const double cutoff_hz = std::max(1.0, u.U) * k.filtCutOff / pi / c;
    const double lp = std::exp(-2 * pi * dt * cutoff_hz);
    kc.alpha_filt = lp * alpha_filt_prev + (1 - lp) * u.alpha;
    kc.dalpha0 = kc.alpha_filt - k.alpha0;
    const double Kalpha = (kc.alpha_filt - alpha_filt_prev) / dt;
    const double Kalpha_f_prev = x.first_pass ? 0.0 : x.Kalpha_f;
    kc.q = Kalpha * c / u.U;
    const double q_prev = x.first_pass ? kc.q : x.q;
    const double q_f_prev = x.first_pass ? kc.q : x.q_f;
    kc.q_f = lp * q_f_prev + (1 - lp) * kc.q;
    kc.Kalpha_f = kc.q_f * u.U / c;
    kc.Kq = (kc.q - q_prev) / dt;
    const double Kq_f_prev = x.first_pass ? 0.0 : x.Kq_f;
    kc.Kq_f = lp * Kq_f_prev + (1 - lp) * kc.Kq;

    const double ab = k.A1 * k.b1 + k.A2 * k.b2;
    kc.k_alpha = 1 / ((1 - M) + k.C_nalpha / 2 * M * M * beta * ab);
    const double k_q = 1 / ((1 - M) + k.C_nalpha * M * M * beta * ab);
    kc.T_I = c / s.speed_of_sound;
    kc.T_alpha = kc.T_I * kc.k_alpha * 0.75;
    kc.T_q = kc.T_I * k_q * 0.75;
    kc.T_f = k.T_f0 / x.sigma1;

    kc.Kprime_alpha = deficiency(dt, kc.T_alpha, x.Kprime_alpha, kc.Kalpha_f, Kalpha_f_prev);
    kc.cn_alpha_nc = 4 * kc.T_alpha * (kc.Kalpha_f - kc.Kprime_alpha) / M;
    kc.Kprime_q = deficiency(dt, kc.T_q, x.Kprime_q, kc.Kq_f, Kq_f_prev);
    kc.cn_q_nc = -kc.T_q * (kc.Kq_f - kc.Kprime_q) / M;
    kc.cn_aq_nc = kc.cn_alpha_nc + kc.cn_q_nc;

    const double dalpha = kc.alpha_filt - alpha_filt_prev;
    kc.X1 = deficiency(kc.ds * beta2 * k.b1, 1, x.X1, k.A1 * dalpha, 0);
    kc.X2 = deficiency(kc.ds * beta2 * k.b2, 1, x.X2, k.A2 * dalpha, 0);
    kc.alpha_e = (kc.alpha_filt - k.alpha0) - kc.X1 - kc.X2;
    kc.cn_aq_circ = kc.cna_circ * kc.alpha_e;

    kc.K3prime_q = deficiency(k.b5 * beta2 * kc.ds, 1, x.K3prime_q, k.A5 * (kc.q_f - q_f_prev), 0);
    kc.cm_q_circ = -k.C_nalpha * (kc.q_f - kc.K3prime_q) * c / (16 * beta * u.U);
    kc.cn_pot = kc.cn_aq_circ + kc.cn_aq_nc;
    const double k_mq = 7 / (15 * (1 - M) + 1.5 * k.C_nalpha * k.A5 * k.b5 * beta * M * M);
    kc.Kprimeprime_q = deficiency(dt, k_mq * k_mq * kc.T_I, x.Kprimeprime_q, kc.Kq_f, Kq_f_prev);
    kc.cm_q_nc =
        -kc.cn_q_nc / 4 - kc.k_alpha * kc.k_alpha * kc.T_I * (kc.Kq_f - kc.Kprimeprime_q) / (3 * M);
    kc.cc_pot = kc.cn_aq_circ * std::tan(kc.alpha_e + k.alpha0);

    const double cn_pot_prev = x.first_pass ? kc.cn_pot : x.cn_pot;
    kc.Dp = deficiency(kc.ds, k.T_p, x.Dp, kc.cn_pot, cn_pot_prev);
    kc.cn_prime = kc.cn_pot - kc.Dp;
    kc.alpha_f = kc.cn_prime / kc.cna_circ + k.alpha0;

    if (!s.f_lookup)
        throw std::invalid_argument("unsteady aerodynamics: UA_Mod 3 needs FLookup True");
    const PolarAt at_alpha_f = polar_at(af, kc.alpha_f);
    kc.fprime = f_from_lookup(af, at_alpha_f, k.alpha0, kc.cna_circ).f;
    kc.Df = x.first_pass ? 0.0 : deficiency(kc.ds, kc.T_f, x.Df, kc.fprime, x.fprime);
    kc.fprimeprime = kc.fprime - kc.Df;
    kc.fprime_c = f_c_from_lookup(af, at_alpha_f, k.alpha0, kc.cna_circ, eta_e);
    // T_fc = T_f0 / sigma1c, and sigma1c stays 1 outside UA_Mod 2.
    kc.Df_c = x.first_pass ? 0.0 : deficiency(kc.ds, k.T_f0, x.Df_c, kc.fprime_c, x.fprime_c);
    kc.fprimeprime_c = kc.fprime_c - kc.Df_c;

    const double cn_fs_sep =
        f_from_lookup(af, polar_at(af, kc.alpha_e + k.alpha0), k.alpha0, kc.cna_circ).cn_fs;
    kc.cn_fs =
        kc.cn_aq_nc + kc.cna_circ * kc.alpha_e * kc.fprimeprime + cn_fs_sep * (1 - kc.fprimeprime);
    kc.Dalphaf =
        x.first_pass ? 0.0 : deficiency(kc.ds, 0.1 * kc.T_f, x.Dalphaf, kc.alpha_f, x.alpha_f);
    kc.C_V = kc.cn_aq_circ * (1 - square(0.5 + 0.5 * std::sqrt(kc.fprimeprime)));
    kc.T_V = k.T_V0 / x.sigma3;
    if (x.first_pass) {
        kc.cn_v = 0;
    } else {
        if (x.tau_V > k.T_VL && kc.Kalpha_f * kc.dalpha0 > 0)
            kc.cn_v = x.cn_v * std::exp(-kc.ds / kc.T_V);
        else
            kc.cn_v = deficiency(kc.ds, kc.T_V, x.cn_v, kc.C_V, x.C_V);
        kc.cn_v = std::max(0.0, kc.cn_v);
    }
}

UnsteadyOutput outputs(const UnsteadyAirfoil& af, const UnsteadySettings& s, double c,
                       const UnsteadyInput& u, const MinnemaPierceState& x, const Chain* kc) {
    const UnsteadyConstants& k = af.constants();
    UnsteadyOutput y;
    y.k = std::abs(u.omega * c / (2 * u.U));
    const double ca = std::cos(u.alpha), sa = std::sin(u.alpha);
    if (kc == nullptr) { // FirstPass: the steady polar at alpha
        const auto p = af.at(u.alpha);
        y.cl = p.cl;
        y.cd = p.cd;
        y.cm = p.cm;
        y.cn = p.cl * ca + (p.cd - k.Cd0) * sa;
        y.cc = p.cl * sa - (p.cd - k.Cd0) * ca;
        y.weight = 0;
        y.alpha_filt = u.alpha;
        return y;
    }
    const double eta_e = s.f_lookup ? 1.0 : k.eta_e;
    y.cn = x.tau_V > 0 ? kc->cn_fs + kc->cn_v : kc->cn_fs;
    const double cc_fs = eta_e * kc->cc_pot * (std::sqrt(kc->fprimeprime_c) - gonzalez_factor);
    y.cc = cc_fs + kc->cn_v * kc->alpha_e * (1 - x.tau_V / k.T_VL);
    y.cl = y.cn * ca + y.cc * sa;
    y.cd = y.cn * sa - y.cc * ca + k.Cd0;
    y.cn = y.cl * ca + y.cd * sa;
    y.cc = y.cl * sa - y.cd * ca;
    y.alpha_prime_f = kc->alpha_f - kc->Dalphaf;
    if (af.has_cm()) {
        const double cm_common = kc->cm_q_circ - kc->cn_alpha_nc / 4 + kc->cm_q_nc;
        const double cm_fs = af.at(y.alpha_prime_f).cm + cm_common;
        y.cm_v = -k.x_cp_bar * (1 - std::cos(pi * x.tau_V / k.T_VL)) * kc->cn_v;
        y.cm = cm_fs + y.cm_v;
    }
    blend_steady(af, u, y);
    y.alpha_filt = kc->alpha_filt;
    y.alpha_e = kc->alpha_e;
    y.alpha_f = kc->alpha_f;
    y.X1 = kc->X1;
    y.X2 = kc->X2;
    y.cn_aq_circ = kc->cn_aq_circ;
    y.cn_aq_nc = kc->cn_aq_nc;
    y.cn_pot = kc->cn_pot;
    y.Dp = kc->Dp;
    y.cn_prime = kc->cn_prime;
    y.fprime = kc->fprime;
    y.Df = kc->Df;
    y.fprimeprime = kc->fprimeprime;
    y.cn_v = kc->cn_v;
    y.C_V = kc->C_V;
    y.tau_V = x.tau_V;
    y.T_f = kc->T_f;
    y.T_V = kc->T_V;
    y.Dalphaf = kc->Dalphaf;
    return y;
}

// UA_UpdateDiscOtherState after the chain.
void update(const UnsteadyConstants& k, const Chain& kc, MinnemaPierceState& x) {
    const double T_sh = 2 * (1 - kc.fprimeprime) / k.St_sh;
    const bool lesf = kc.cn_prime > k.Cn1 || kc.cn_prime < k.Cn2;
    const bool tesf = kc.fprimeprime < x.fprimeprime;
    const bool vrtx = x.tau_V <= k.T_VL && x.tau_V > 0;
    const double ka = kc.Kalpha_f * kc.dalpha0; // < 0: moving toward alpha0

    double sigma1 = 1;
    if (tesf) {
        if (ka < 0)
            sigma1 = 2;
        else if (!lesf)
            sigma1 = 1;
        else if (x.fprimeprime <= 0.7)
            sigma1 = 2;
        else
            sigma1 = 1.75;
    } else {
        if (!lesf) sigma1 = 0.5;
        if (vrtx) sigma1 = 0.25;
        if (ka > 0) sigma1 = 0.75;
    }
    double sigma3 = 1;
    if (x.tau_V <= 2 * k.T_VL && x.tau_V >= k.T_VL)
        sigma3 = tesf ? 3 : 4;
    else if (vrtx)
        sigma3 = ka < 0 ? 2 : 1;
    else if (ka < 0)
        sigma3 = 4;
    if (!tesf && kc.Kq_f * kc.dalpha0 < 0) sigma3 = 1;

    x.sigma1 = sigma1;
    x.sigma3 = sigma3;
    x.alpha_filt = kc.alpha_filt;
    x.Kalpha_f = kc.Kalpha_f;
    x.Kq_f = kc.Kq_f;
    x.q_f = kc.q_f;
    x.q = kc.q;
    x.X1 = kc.X1;
    x.X2 = kc.X2;
    x.Kprime_alpha = kc.Kprime_alpha;
    x.Kprime_q = kc.Kprime_q;
    x.K3prime_q = kc.K3prime_q;
    x.Kprimeprime_q = kc.Kprimeprime_q;
    x.Dp = kc.Dp;
    x.cn_pot = kc.cn_pot;
    x.cn_prime = kc.cn_prime;
    x.fprimeprime = kc.fprimeprime;
    x.Df = kc.Df;
    x.Df_c = kc.Df_c;
    x.fprime_c = kc.fprime_c;
    x.Dalphaf = kc.Dalphaf;
    x.fprime = kc.fprime;
    x.alpha_f = kc.alpha_f;
    x.cn_v = kc.cn_v;
    x.C_V = kc.C_V;
    if (x.tau_V > 0 || lesf) x.tau_V += kc.ds;
    if (x.tau_V >= k.T_VL + T_sh && tesf) x.tau_V = 0;
    x.first_pass = false;
}

void require_model(const UnsteadySettings& s) {
    if (s.model != UnsteadyModel::minnema_pierce)
        throw std::invalid_argument("unsteady aerodynamics: these states are UA_Mod 3's");
}

} // namespace

UnsteadyOutput evaluate(const UnsteadyAirfoil& af, const UnsteadySettings& s, double chord,
                        double dt, const UnsteadyInput& in, const MinnemaPierceState& x) {
    MinnemaPierceMemo none;
    return evaluate(af, s, chord, dt, in, x, none);
}

UnsteadyOutput step(const UnsteadyAirfoil& af, const UnsteadySettings& s, double chord, double dt,
                    const UnsteadyInput& in, MinnemaPierceState& x) {
    MinnemaPierceMemo none;
    return step(af, s, chord, dt, in, x, none);
}

namespace {

bool same_input(const MinnemaPierceMemo::Entry& e, const UnsteadyInput& u, double dt) {
    return e.valid && e.dt == dt && e.u.U == u.U && e.u.alpha == u.alpha && e.u.omega == u.omega &&
           e.u.v_ac_n == u.v_ac_n && e.u.v_ac_c == u.v_ac_c;
}

} // namespace

UnsteadyOutput evaluate(const UnsteadyAirfoil& af, const UnsteadySettings& s, double chord,
                        double dt, const UnsteadyInput& in, const MinnemaPierceState& x,
                        MinnemaPierceMemo& memo) {
    require_model(s);
    const UnsteadyInput u = fixed(in);
    if (x.first_pass) return outputs(af, s, chord, u, x, nullptr);
    MinnemaPierceMemo::Entry& e = memo.entries[memo.next];
    memo.next = 1 - memo.next;
    e.valid = false; // until the chain is complete (it may throw)
    kelvin_chain(af, s, chord, dt, u, x, e.chain);
    e.u = u;
    e.dt = dt;
    e.valid = true;
    return outputs(af, s, chord, u, x, &e.chain);
}

namespace {

// The chain of (u, dt) from the state x: the memo's (no copy), else computed into
// `own`.
const Chain& chain_for_step(const UnsteadyAirfoil& af, const UnsteadySettings& s, double chord,
                            double dt, const UnsteadyInput& u, const MinnemaPierceState& x,
                            const MinnemaPierceMemo& memo, Chain& own) {
    for (const auto& e : memo.entries)
        if (same_input(e, u, dt)) return e.chain;
    kelvin_chain(af, s, chord, dt, u, x, own);
    return own;
}

// The memo emptied, as the state has changed.
void forget(MinnemaPierceMemo& memo) {
    for (auto& e : memo.entries) e.valid = false;
    memo.next = 0;
}

} // namespace

UnsteadyOutput step(const UnsteadyAirfoil& af, const UnsteadySettings& s, double chord, double dt,
                    const UnsteadyInput& in, MinnemaPierceState& x, MinnemaPierceMemo& memo) {
    require_model(s);
    const UnsteadyInput u = fixed(in);
    Chain own;
    const Chain& kc = chain_for_step(af, s, chord, dt, u, x, memo, own);
    const UnsteadyOutput y = outputs(af, s, chord, u, x, x.first_pass ? nullptr : &kc);
    update(af.constants(), kc, x);
    forget(memo);
    return y;
}

void advance(const UnsteadyAirfoil& af, const UnsteadySettings& s, double chord, double dt,
             const UnsteadyInput& in, MinnemaPierceState& x, MinnemaPierceMemo& memo) {
    require_model(s);
    const UnsteadyInput u = fixed(in);
    Chain own;
    update(af.constants(), chain_for_step(af, s, chord, dt, u, x, memo, own), x);
    forget(memo);
}

} // namespace yamsc::aero
