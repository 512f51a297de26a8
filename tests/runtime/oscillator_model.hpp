#pragma once
// A hand-written model in the shape of generated code (docs/generated-api.md):
// the damped harmonic oscillator m x'' + c x' + k x = f. Standard headers only,
// because the shared-library test compiles it on the fly as well.
#include <cmath>

namespace test_oscillator {

inline constexpr int nq = 1, nu = 1, np = 3, ny = 2;
inline constexpr const char* dof_names[nq] = {"x"};
inline constexpr const char* input_names[nu] = {"f"};
inline constexpr const char* param_names[np] = {"m", "c", "k"};
inline constexpr const char* output_names[ny] = {"spring_force", "kinetic_energy"};

struct Params {
    double m = 2.0;
    double c = 0.4;
    double k = 50.0;
};

struct Model {
    static constexpr int nq = test_oscillator::nq, nu = test_oscillator::nu,
                         np = test_oscillator::np, ny = test_oscillator::ny;
    using Params = test_oscillator::Params;
    static constexpr const char* const* dof_names = test_oscillator::dof_names;
    static constexpr const char* const* input_names = test_oscillator::input_names;
    static constexpr const char* const* param_names = test_oscillator::param_names;
    static constexpr const char* const* output_names = test_oscillator::output_names;

    static void mass_matrix(double, const double*, const double*, const Params& p, double* M) {
        M[0] = p.m;
    }
    static void forcing(double, const double* q, const double* qd, const double* u, const Params& p,
                        double* F) {
        F[0] = u[0] - p.c * qd[0] - p.k * q[0];
    }
    static void rhs(double t, const double* x, const double* u, const Params& p, double* xdot) {
        double F[1];
        forcing(t, x, x + 1, u, p, F);
        xdot[0] = x[1];
        xdot[1] = F[0] / p.m;
    }
    static void jacobians(double, const double*, const double*, const double*, const Params& p,
                          double* dF_dq, double* dF_dqd, double* dF_du) {
        dF_dq[0] = -p.k;
        dF_dqd[0] = -p.c;
        dF_du[0] = 1.0;
    }
    static void rhs_jacobian(double, const double*, const double*, const Params& p, double* J) {
        J[0] = 0.0;
        J[1] = 1.0;
        J[2] = -p.k / p.m;
        J[3] = -p.c / p.m;
    }
    static void outputs(double, const double* q, const double* qd, const double*, const Params& p,
                        double* y) {
        y[0] = p.k * q[0];
        y[1] = 0.5 * p.m * qd[0] * qd[0];
    }
    static void params_to_array(const Params& p, double* a) {
        a[0] = p.m;
        a[1] = p.c;
        a[2] = p.k;
    }
    static Params params_from_array(const double* a) { return Params{a[0], a[1], a[2]}; }
};

} // namespace test_oscillator
