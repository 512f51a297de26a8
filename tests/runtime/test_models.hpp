#pragma once
// Hand-made models with known solutions, in the shape of generated code, and
// the closed-form references the tests compare against.
#include "runtime/oscillator_model.hpp"

#include <cmath>

namespace test_pendulum {

// m l^2 q'' = -m g l sin q; output: the total energy, which must stay constant.
inline constexpr int nq = 1, nu = 0, np = 3, ny = 1;
inline constexpr const char* dof_names[nq] = {"phi"};
inline constexpr const char* input_names[1] = {""};
inline constexpr const char* param_names[np] = {"m", "l", "g"};
inline constexpr const char* output_names[ny] = {"energy"};

struct Params {
    double m = 1.5;
    double l = 0.8;
    double g = 9.81;
};

struct Model {
    static constexpr int nq = test_pendulum::nq, nu = test_pendulum::nu, np = test_pendulum::np,
                         ny = test_pendulum::ny;
    using Params = test_pendulum::Params;
    static constexpr const char* const* dof_names = test_pendulum::dof_names;
    static constexpr const char* const* input_names = test_pendulum::input_names;
    static constexpr const char* const* param_names = test_pendulum::param_names;
    static constexpr const char* const* output_names = test_pendulum::output_names;

    static void mass_matrix(double, const double*, const double*, const Params& p, double* M) {
        M[0] = p.m * p.l * p.l;
    }
    static void forcing(double, const double* q, const double*, const double*, const Params& p,
                        double* F) {
        F[0] = -p.m * p.g * p.l * std::sin(q[0]);
    }
    static void rhs(double, const double* x, const double*, const Params& p, double* xdot) {
        xdot[0] = x[1];
        xdot[1] = -p.g / p.l * std::sin(x[0]);
    }
    static void jacobians(double, const double* q, const double*, const double*, const Params& p,
                          double* dF_dq, double* dF_dqd, double*) {
        dF_dq[0] = -p.m * p.g * p.l * std::cos(q[0]);
        dF_dqd[0] = 0.0;
    }
    static void rhs_jacobian(double, const double* x, const double*, const Params& p, double* J) {
        J[0] = 0.0;
        J[1] = 1.0;
        J[2] = -p.g / p.l * std::cos(x[0]);
        J[3] = 0.0;
    }
    static void outputs(double, const double* q, const double* qd, const double*, const Params& p,
                        double* y) {
        y[0] = 0.5 * p.m * p.l * p.l * qd[0] * qd[0] + p.m * p.g * p.l * (1.0 - std::cos(q[0]));
    }
    static void params_to_array(const Params& p, double* a) {
        a[0] = p.m;
        a[1] = p.l;
        a[2] = p.g;
    }
    static Params params_from_array(const double* a) { return Params{a[0], a[1], a[2]}; }
};

} // namespace test_pendulum

namespace test_two_masses {

// Two masses in a row: ground -k1- m1 -k2- m2 -k3- ground, Rayleigh damping
// C = alpha M + beta K. With k1 = k3 = 0 the pair floats freely.
inline constexpr int nq = 2, nu = 0, np = 7, ny = 0;
inline constexpr const char* dof_names[nq] = {"x1", "x2"};
inline constexpr const char* input_names[1] = {""};
inline constexpr const char* param_names[np] = {"m1", "m2", "k1", "k2", "k3", "alpha", "beta"};
inline constexpr const char* output_names[1] = {""};

struct Params {
    double m1 = 1.0, m2 = 3.0;
    double k1 = 40.0, k2 = 15.0, k3 = 25.0;
    double alpha = 0.0, beta = 0.0;
};

struct Model {
    static constexpr int nq = test_two_masses::nq, nu = test_two_masses::nu,
                         np = test_two_masses::np, ny = test_two_masses::ny;
    using Params = test_two_masses::Params;
    static constexpr const char* const* dof_names = test_two_masses::dof_names;
    static constexpr const char* const* input_names = test_two_masses::input_names;
    static constexpr const char* const* param_names = test_two_masses::param_names;
    static constexpr const char* const* output_names = test_two_masses::output_names;

    static void stiffness(const Params& p, double* K) {
        K[0] = p.k1 + p.k2;
        K[1] = -p.k2;
        K[2] = -p.k2;
        K[3] = p.k2 + p.k3;
    }
    static void damping(const Params& p, double* C) {
        double K[4];
        stiffness(p, K);
        const double M[4] = {p.m1, 0.0, 0.0, p.m2};
        for (int i = 0; i < 4; ++i) C[i] = p.alpha * M[i] + p.beta * K[i];
    }
    static void mass_matrix(double, const double*, const double*, const Params& p, double* M) {
        M[0] = p.m1;
        M[1] = 0.0;
        M[2] = 0.0;
        M[3] = p.m2;
    }
    static void forcing(double, const double* q, const double* qd, const double*, const Params& p,
                        double* F) {
        double K[4], C[4];
        stiffness(p, K);
        damping(p, C);
        for (int i = 0; i < 2; ++i)
            F[i] = -(K[2 * i] * q[0] + K[2 * i + 1] * q[1]) -
                   (C[2 * i] * qd[0] + C[2 * i + 1] * qd[1]);
    }
    static void rhs(double t, const double* x, const double* u, const Params& p, double* xdot) {
        double F[2];
        forcing(t, x, x + 2, u, p, F);
        xdot[0] = x[2];
        xdot[1] = x[3];
        xdot[2] = F[0] / p.m1;
        xdot[3] = F[1] / p.m2;
    }
    static void jacobians(double, const double*, const double*, const double*, const Params& p,
                          double* dF_dq, double* dF_dqd, double*) {
        double K[4], C[4];
        stiffness(p, K);
        damping(p, C);
        for (int i = 0; i < 4; ++i) {
            dF_dq[i] = -K[i];
            dF_dqd[i] = -C[i];
        }
    }
    static void rhs_jacobian(double, const double*, const double*, const Params& p, double* J) {
        double K[4], C[4];
        stiffness(p, K);
        damping(p, C);
        const double inverse_mass[2] = {1.0 / p.m1, 1.0 / p.m2};
        for (int i = 0; i < 16; ++i) J[i] = 0.0;
        J[0 * 4 + 2] = 1.0;
        J[1 * 4 + 3] = 1.0;
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                J[(2 + i) * 4 + j] = -K[2 * i + j] * inverse_mass[i];
                J[(2 + i) * 4 + 2 + j] = -C[2 * i + j] * inverse_mass[i];
            }
    }
    static void outputs(double, const double*, const double*, const double*, const Params&,
                        double*) {}
    static void params_to_array(const Params& p, double* a) {
        const double values[np] = {p.m1, p.m2, p.k1, p.k2, p.k3, p.alpha, p.beta};
        for (int i = 0; i < np; ++i) a[i] = values[i];
    }
    static Params params_from_array(const double* a) {
        return Params{a[0], a[1], a[2], a[3], a[4], a[5], a[6]};
    }
};

} // namespace test_two_masses

namespace reference {

// Exact motion of the damped oscillator m x'' + c x' + k x = f (f constant,
// underdamped) from x(0) = x0, x'(0) = v0.
struct OscillatorSolution {
    double x, v;
};
inline OscillatorSolution oscillator(const test_oscillator::Params& p, double f, double x0,
                                     double v0, double t) {
    const double wn = std::sqrt(p.k / p.m);
    const double zeta = p.c / (2.0 * std::sqrt(p.k * p.m));
    const double sigma = zeta * wn, wd = wn * std::sqrt(1.0 - zeta * zeta);
    const double x_eq = f / p.k, a = x0 - x_eq, b = (v0 + sigma * a) / wd;
    const double decay = std::exp(-sigma * t), c = std::cos(wd * t), s = std::sin(wd * t);
    return {x_eq + decay * (a * c + b * s),
            decay * ((-sigma * a + wd * b) * c + (-sigma * b - wd * a) * s)};
}

} // namespace reference
