#include "yamsc/aero/dynamic_inflow.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace yamsc::aero {

namespace {

constexpr double k0 = Dbemt::k_0ye;

// tau2 / tau1 at r / R (ComputeTau2).
double k_tau_at(double span_ratio) {
    return 0.39 - 0.26 * span_ratio * span_ratio;
}

// Øye's filters for a quasi-steady input w0 + rate * s over a step of dt, exactly
// (AeroDyn's DBEMT theory, eqs. 1.17-1.25): w1 is W_int, w is W; e1 = exp(-dt/tau1),
// e2 = exp(-dt/tau2).
struct StepConstants {
    double tau1, tau2, k_tau, e1, e2;
};
void exact_step(double w0, double rate, const StepConstants& c, double dt, double& w1, double& w) {
    const double a = w0 + rate * k0 * c.tau1;
    const double c1 = w1 - a + rate * c.tau1;
    w1 = c1 * c.e1 + a + rate * (dt - c.tau1);
    const double c1_2 = c1 / (1 - c.k_tau);
    const double c2 = w - c1_2 - a + rate * (c.tau1 + c.tau2);
    w = c2 * c.e2 + a + rate * (dt - c.tau1 - c.tau2) + c1_2 * c.e1;
}

// DBEMT_CalcContStateDeriv for one element: x = [W ax, W tan, W_red ax, W_red tan].
void element_derivative(double tau1, double tau2, InducedVelocity qs, const double* x,
                        double* dxdt) {
    const double w_qs[2] = {qs.axial, qs.tangential};
    for (int c = 0; c < 2; ++c) {
        dxdt[2 + c] = ((1 - k0) * w_qs[c] - x[2 + c]) / tau1;
        dxdt[c] = (x[2 + c] - x[c] + k0 * w_qs[c]) / tau2;
    }
}

InducedVelocity lerp(InducedVelocity a, InducedVelocity b, double s) {
    return {a.axial + s * (b.axial - a.axial), a.tangential + s * (b.tangential - a.tangential)};
}

void fail(const std::string& what) {
    throw std::invalid_argument("dynamic inflow: " + what);
}

} // namespace

Dbemt::Dbemt(DynamicInflow model, double tau1_const, double dt, int blades, int nodes,
             const std::vector<double>& rlocal_init)
    : model_(model), tau1_const_(tau1_const), dt_(dt), blades_(blades), nodes_(nodes) {
    if (model == DynamicInflow::none) fail("DBEMT_Mod must be 1, 2 or 3");
    if (!(dt > std::sqrt(std::numeric_limits<double>::epsilon())))
        fail("the time step must be larger than sqrt(epsilon)");
    if (blades < 1) fail("a rotor needs at least one blade");
    if (nodes < 2) fail("a blade needs at least two nodes");
    const std::size_t n = std::size_t(blades) * std::size_t(nodes);
    if (rlocal_init.size() != n) fail("one rlocal per blade node is needed");
    const bool constant_tau1 = model != DynamicInflow::varying_tau1;
    if (constant_tau1 && !(tau1_const > 0)) fail("tau1_const must be greater than zero");
    if (constant_tau1 && *std::min_element(rlocal_init.begin(), rlocal_init.end()) <= 0)
        fail("blade nodes must lie at a positive distance from the rotor axis");
    const double r_tip = *std::max_element(rlocal_init.begin(), rlocal_init.end());
    if (!(r_tip > 0)) fail("the blades have no node away from the rotor axis");

    span_ratio_.resize(n);
    for (std::size_t e = 0; e < n; ++e) span_ratio_[e] = rlocal_init[e] / r_tip;
    if (constant_tau1) { // the filters' decay over a step, the same every step
        exp_tau1_ = std::exp(-dt / tau1_const);
        exp_tau2_.resize(n);
        for (std::size_t e = 0; e < n; ++e)
            exp_tau2_[e] = std::exp(-dt / (k_tau_at(span_ratio_[e]) * tau1_const));
    }

    // BEMT_SetParameters: a triweight kernel of half-width 0.1 R around 0.7 R, normalized
    // on each blade, then divided by the number of blades.
    disk_weight_.assign(n, 0.0);
    for (int b = 0; b < blades; ++b) {
        double sum = 0;
        for (int i = 0; i < nodes; ++i) {
            const std::size_t e = std::size_t(b) * std::size_t(nodes) + std::size_t(i);
            const double x = std::clamp((span_ratio_[e] - 0.7) / 0.1, -1.0, 1.0);
            const double w = 35.0 / 32.0 * std::pow(1 - x * x, 3);
            disk_weight_[e] = w;
            sum += w;
        }
        for (int i = 0; i < nodes; ++i) {
            double& w = disk_weight_[std::size_t(b) * std::size_t(nodes) + std::size_t(i)];
            if (sum > 0) w /= sum;
            w /= blades;
        }
    }
}

DbemtInput Dbemt::make_input() const {
    DbemtInput u;
    u.quasi_steady.resize(elements());
    u.rlocal.assign(elements(), 0.0);
    return u;
}

DbemtState Dbemt::make_state() const {
    DbemtState x;
    x.element.resize(elements());
    x.tau1 = model_ == DynamicInflow::varying_tau1 ? 0.0 : tau1_const_;
    return x;
}

double Dbemt::tau1(const DbemtDiskInput& disk) const {
    if (model_ != DynamicInflow::varying_tau1) return tau1_const_;
    // ComputeTau1 bounds the induction and the speed (warning once; here silently) and
    // the result, which keeps a start from rest finite.
    const double a = std::min(disk.axial_induction, 0.5);
    const double un = std::max(disk.normal_speed, 0.1);
    return std::min(1.1 * disk.radius / ((1 - 1.3 * a) * un), 100.0);
}

double Dbemt::k_tau(const DbemtInput& u, std::size_t e) const {
    return k_tau_at(model_ == DynamicInflow::varying_tau1 ? u.rlocal[e] / u.disk.radius
                                                          : span_ratio_[e]);
}

void Dbemt::set_disk_input(DbemtInput& u, const double* a, double normal_speed) const {
    double a_disk = 0;
    for (std::size_t e = 0; e < elements(); ++e) a_disk += a[e] * disk_weight_[e];
    u.disk.axial_induction = a_disk;
    u.disk.normal_speed = normal_speed;
    u.disk.radius = *std::max_element(u.rlocal.begin(), u.rlocal.end());
}

void Dbemt::initialize(const DbemtInput& u, DbemtState& x) const {
    if (x.initialized) return;
    const double scale = model_ == DynamicInflow::continuous ? 1 - k0 : 1.0;
    for (std::size_t e = 0; e < elements(); ++e) {
        const InducedVelocity qs = u.quasi_steady[e];
        x.element[e].vind = qs;
        x.element[e].vind_1 = {scale * qs.axial, scale * qs.tangential};
    }
    x.initialized = true;
}

void Dbemt::update(const DbemtInput& u_t, const DbemtInput& u_next, DbemtState& x) const {
    x.tau1 = tau1(u_t.disk);
    initialize(u_t, x);
    if (model_ == DynamicInflow::continuous)
        update_rk4(u_t, u_next, x);
    else
        update_discrete(u_t, u_next, x);
}

void Dbemt::update_discrete(const DbemtInput& u_t, const DbemtInput& u_next, DbemtState& x) const {
    const bool varying = model_ == DynamicInflow::varying_tau1;
    StepConstants c{};
    c.tau1 = x.tau1;
    c.e1 = varying ? std::exp(-dt_ / c.tau1) : exp_tau1_;
    for (std::size_t e = 0; e < elements(); ++e) {
        c.k_tau = k_tau(u_t, e);
        c.tau2 = c.k_tau * c.tau1;
        c.e2 = varying ? std::exp(-dt_ / c.tau2) : exp_tau2_[e];
        const InducedVelocity q0 = u_t.quasi_steady[e], q1 = u_next.quasi_steady[e];
        DbemtElementState& s = x.element[e];
        // AeroDyn filters the tangential component as the axial one.
        exact_step(q0.axial, (q1.axial - q0.axial) / dt_, c, dt_, s.vind_1.axial, s.vind.axial);
        exact_step(q0.tangential, (q1.tangential - q0.tangential) / dt_, c, dt_,
                   s.vind_1.tangential, s.vind.tangential);
    }
}

void Dbemt::update_rk4(const DbemtInput& u_t, const DbemtInput& u_next, DbemtState& x) const {
    // DBEMT_RK4 with the input interpolated linearly in the step (AeroDyn continues
    // with ABM4 from the third step; both are exact to far below the filters' accuracy).
    const double tau1 = tau1_const_;
    for (std::size_t e = 0; e < elements(); ++e) {
        const double tau2 = k_tau(u_t, e) * tau1;
        const InducedVelocity q0 = u_t.quasi_steady[e], q1 = u_next.quasi_steady[e];
        const InducedVelocity qh = lerp(q0, q1, 0.5);
        DbemtElementState& s = x.element[e];
        const double x0[4] = {s.vind.axial, s.vind.tangential, s.vind_1.axial, s.vind_1.tangential};
        double k1[4], k2[4], k3[4], k4[4], xt[4];
        element_derivative(tau1, tau2, q0, x0, k1);
        for (int c = 0; c < 4; ++c) xt[c] = x0[c] + 0.5 * dt_ * k1[c];
        element_derivative(tau1, tau2, qh, xt, k2);
        for (int c = 0; c < 4; ++c) xt[c] = x0[c] + 0.5 * dt_ * k2[c];
        element_derivative(tau1, tau2, qh, xt, k3);
        for (int c = 0; c < 4; ++c) xt[c] = x0[c] + dt_ * k3[c];
        element_derivative(tau1, tau2, q1, xt, k4);
        double x1[4];
        for (int c = 0; c < 4; ++c)
            x1[c] = x0[c] + dt_ / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
        s.vind = {x1[0], x1[1]};
        s.vind_1 = {x1[2], x1[3]};
    }
}

void Dbemt::derivative(const DbemtInput& u, const double* x, double* dxdt) const {
    for (std::size_t e = 0; e < elements(); ++e) {
        const std::size_t o = e * states_per_element;
        element_derivative(tau1_const_, k_tau(u, e) * tau1_const_, u.quasi_steady[e], x + o,
                           dxdt + o);
    }
}

void Dbemt::pack(const DbemtState& x, double* flat) {
    for (const DbemtElementState& s : x.element) {
        *flat++ = s.vind.axial;
        *flat++ = s.vind.tangential;
        *flat++ = s.vind_1.axial;
        *flat++ = s.vind_1.tangential;
    }
}

void Dbemt::unpack(const double* flat, DbemtState& x) {
    for (DbemtElementState& s : x.element) {
        s.vind = {flat[0], flat[1]};
        s.vind_1 = {flat[2], flat[3]};
        flat += states_per_element;
    }
}

InductionFactors induction_factors(InducedVelocity w, double vx, double vy) {
    // EqualRealNos(v, 0) and limitInductionFactors of AeroDyn.
    constexpr double tol = 50 * std::numeric_limits<double>::epsilon();
    const auto zero = [](double v) { return std::abs(v) <= std::max(std::abs(v), 1.0) * tol; };
    InductionFactors f;
    f.axial = zero(vx) ? 0.0 : std::clamp(-w.axial / vx, -1.0, 1.5);
    f.tangential = zero(vy) ? 0.0 : std::clamp(w.tangential / vy, -1.0, 1.0);
    return f;
}

} // namespace yamsc::aero
