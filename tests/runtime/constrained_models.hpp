#pragma once
// Hand-written views with constraint rows and their closed forms
// (docs/constraints.md): a pendulum in Cartesian coordinates, the Chaplygin
// sleigh (a knife edge, nonholonomic) and a pendulum whose angle is prescribed.
#include "yamsc/model_view.hpp"

#include <cmath>

namespace test_constrained {

/// A point mass m on a massless rod of length L from the origin, in x and y (y
/// up): Phi = x^2 + y^2 - L^2. The rod's tension is -2 L lambda.
struct Pendulum {
    double m = 1.3, L = 0.8, g = 9.81;
};

inline yamsc::runtime::ModelView cartesian_pendulum(const Pendulum& p) {
    yamsc::runtime::ModelView v;
    v.nq = 2;
    v.dof_names = {"x", "y"};
    v.ny = 1;
    v.output_names = {"ydd"};
    v.nh = v.nc = 1;
    v.constraint_names = {"rod"};
    v.constraint_dependent = {-1};
    v.constraint_sources = {"pendulum.mbd:3:1"};
    v.mass_matrix = [p](double, const double*, const double*, double* M) {
        M[0] = M[3] = p.m;
        M[1] = M[2] = 0;
    };
    v.forcing = [p](double, const double*, const double*, const double*, double* F) {
        F[0] = 0;
        F[1] = -p.m * p.g;
    };
    v.jacobians = [](double, const double*, const double*, const double*, double* dq, double* dqd,
                     double*) {
        for (int i = 0; i < 4; ++i) dq[i] = dqd[i] = 0;
    };
    v.rhs = [p](double, const double* x, const double*, double* xdot) {
        xdot[0] = x[2];
        xdot[1] = x[3];
        xdot[2] = 0;
        xdot[3] = -p.g;
    };
    v.outputs = [p](double, const double*, const double*, const double*, double* y) {
        y[0] = -p.g;
    };
    v.outputs_from_qdd = [](double, const double*, const double*, const double* qdd, const double*,
                            double* y) { y[0] = qdd[1]; };
    v.constraint_residuals = [p](double, const double* q, const double* qd, const double*,
                                 double* phi, double* r) {
        phi[0] = q[0] * q[0] + q[1] * q[1] - p.L * p.L;
        r[0] = 2 * q[0] * qd[0] + 2 * q[1] * qd[1];
    };
    v.constraint_matrix = [](double, const double* q, const double*, double* B) {
        B[0] = 2 * q[0];
        B[1] = 2 * q[1];
    };
    v.constraint_bias = [](double, const double*, const double* qd, const double*, double* gamma,
                           double* dr_dq) {
        gamma[0] = 2 * (qd[0] * qd[0] + qd[1] * qd[1]);
        dr_dq[0] = 2 * qd[0];
        dr_dq[1] = 2 * qd[1];
    };
    v.constraint_jacobians = [](double, const double*, const double* qd, const double*,
                                const double* lambda, const double* a, double* dBTl_dq,
                                double* dacc_dq, double* dacc_dqd, double*, double*) {
        dBTl_dq[0] = dBTl_dq[3] = 2 * lambda[0];
        dBTl_dq[1] = dBTl_dq[2] = 0;
        dacc_dq[0] = 2 * a[0];
        dacc_dq[1] = 2 * a[1];
        dacc_dqd[0] = 4 * qd[0];
        dacc_dqd[1] = 4 * qd[1];
    };
    return v;
}

/// The Chaplygin sleigh: a body of mass m and inertia I about its centre of
/// mass, on a knife edge at (x, y) with heading psi, the centre of mass b
/// ahead of it; the edge does not slip sideways: -sin psi x' + cos psi y' = 0.
struct Sleigh {
    double m = 2.0, I = 0.3, b = 0.25;
};

inline yamsc::runtime::ModelView chaplygin_sleigh(const Sleigh& p, bool exact_mass_action) {
    yamsc::runtime::ModelView v;
    v.nq = 3;
    v.dof_names = {"x", "y", "psi"};
    v.nh = 0;
    v.nc = 1;
    v.constraint_names = {"edge"};
    v.constraint_dependent = {-1};
    v.constraint_sources = {"sleigh.mbd:9:1"};
    v.mass_matrix = [p](double, const double* q, const double*, double* M) {
        const double s = std::sin(q[2]), c = std::cos(q[2]);
        const double M_[9] = {p.m,
                              0,
                              -p.m * p.b * s,
                              0,
                              p.m,
                              p.m * p.b * c,
                              -p.m * p.b * s,
                              p.m * p.b * c,
                              p.I + p.m * p.b * p.b};
        for (int i = 0; i < 9; ++i) M[i] = M_[i];
    };
    v.forcing = [p](double, const double* q, const double* qd, const double*, double* F) {
        const double w2 = qd[2] * qd[2];
        F[0] = p.m * p.b * std::cos(q[2]) * w2;
        F[1] = p.m * p.b * std::sin(q[2]) * w2;
        F[2] = 0;
    };
    v.jacobians = [p](double, const double* q, const double* qd, const double*, double* dq,
                      double* dqd, double*) {
        const double s = std::sin(q[2]), c = std::cos(q[2]), w = qd[2];
        for (int i = 0; i < 9; ++i) dq[i] = dqd[i] = 0;
        dq[2] = -p.m * p.b * s * w * w;
        dq[5] = p.m * p.b * c * w * w;
        dqd[2] = 2 * p.m * p.b * c * w;
        dqd[5] = 2 * p.m * p.b * s * w;
    };
    if (exact_mass_action)
        v.mass_action_jacobian = [p](double, const double* q, const double* a, const double*,
                                     double* D) {
            const double s = std::sin(q[2]), c = std::cos(q[2]);
            for (int i = 0; i < 9; ++i) D[i] = 0;
            D[2] = -p.m * p.b * c * a[2];
            D[5] = -p.m * p.b * s * a[2];
            D[8] = -p.m * p.b * (c * a[0] + s * a[1]);
        };
    v.constraint_residuals = [](double, const double* q, const double* qd, const double*, double*,
                                double* r) {
        r[0] = -std::sin(q[2]) * qd[0] + std::cos(q[2]) * qd[1];
    };
    v.constraint_matrix = [](double, const double* q, const double*, double* B) {
        B[0] = -std::sin(q[2]);
        B[1] = std::cos(q[2]);
        B[2] = 0;
    };
    v.constraint_bias = [](double, const double* q, const double* qd, const double*, double* gamma,
                           double* dr_dq) {
        const double s = std::sin(q[2]), c = std::cos(q[2]);
        gamma[0] = -qd[2] * (c * qd[0] + s * qd[1]);
        dr_dq[0] = dr_dq[1] = 0;
        dr_dq[2] = -(c * qd[0] + s * qd[1]);
    };
    v.constraint_jacobians = [](double, const double* q, const double* qd, const double*,
                                const double* lambda, const double* a, double* dBTl_dq,
                                double* dacc_dq, double* dacc_dqd, double*, double*) {
        const double s = std::sin(q[2]), c = std::cos(q[2]);
        for (int i = 0; i < 9; ++i) dBTl_dq[i] = 0;
        dBTl_dq[2] = -c * lambda[0];
        dBTl_dq[5] = -s * lambda[0];
        dacc_dq[0] = dacc_dq[1] = 0;
        dacc_dq[2] = -c * a[0] - s * a[1] - qd[2] * (-s * qd[0] + c * qd[1]);
        dacc_dqd[0] = -qd[2] * c;
        dacc_dqd[1] = -qd[2] * s;
        dacc_dqd[2] = -(c * qd[0] + s * qd[1]);
    };
    return v;
}

/// A pendulum (point mass m at length L, angle theta from hanging) whose angle
/// is prescribed: theta = A sin(w t). lambda is the holding torque.
struct Prescribed {
    double m = 0.7, L = 1.1, g = 9.81, A = 0.4, w = 2.3;
};

inline yamsc::runtime::ModelView prescribed_pendulum(const Prescribed& p) {
    yamsc::runtime::ModelView v;
    v.nq = 1;
    v.dof_names = {"theta"};
    v.nh = v.nc = 1;
    v.constraint_names = {"drive"};
    v.constraint_dependent = {0};
    v.constraint_sources = {"drive.mbd:4:1"};
    v.mass_matrix = [p](double, const double*, const double*, double* M) {
        M[0] = p.m * p.L * p.L;
    };
    v.forcing = [p](double, const double* q, const double*, const double*, double* F) {
        F[0] = -p.m * p.g * p.L * std::sin(q[0]);
    };
    v.jacobians = [p](double, const double* q, const double*, const double*, double* dq,
                      double* dqd, double*) {
        dq[0] = -p.m * p.g * p.L * std::cos(q[0]);
        dqd[0] = 0;
    };
    v.constraint_residuals = [p](double t, const double* q, const double* qd, const double*,
                                 double* phi, double* r) {
        phi[0] = q[0] - p.A * std::sin(p.w * t);
        r[0] = qd[0] - p.A * p.w * std::cos(p.w * t);
    };
    v.constraint_matrix = [](double, const double*, const double*, double* B) { B[0] = 1; };
    v.constraint_bias = [p](double t, const double*, const double*, const double*, double* gamma,
                            double* dr_dq) {
        gamma[0] = p.A * p.w * p.w * std::sin(p.w * t);
        dr_dq[0] = 0;
    };
    v.constraint_jacobians = [](double, const double*, const double*, const double*, const double*,
                                const double*, double* dBTl_dq, double* dacc_dq, double* dacc_dqd,
                                double*, double*) { dBTl_dq[0] = dacc_dq[0] = dacc_dqd[0] = 0; };
    return v;
}

} // namespace test_constrained
