#pragma once
// A free unit mass driven by its one input, the force f: q'' = f, output q. The
// view load-block tests close blocks around (their loads go to f).
#include "yamsc/model_view.hpp"

namespace test_free_mass {

inline yamsc::runtime::ModelView view() {
    yamsc::runtime::ModelView v;
    v.nq = v.nu = v.ny = 1;
    v.input_names = {"f"};
    v.output_names = {"q"};
    v.rhs = [](double, const double* x, const double* u, double* xdot) {
        xdot[0] = x[1];
        xdot[1] = u[0];
    };
    v.rhs_jacobian = [](double, const double*, const double*, double* J) {
        J[0] = 0;
        J[1] = 1;
        J[2] = 0;
        J[3] = 0;
    };
    v.outputs = [](double, const double* q, const double*, const double*, double* y) {
        y[0] = q[0];
    };
    return v;
}

} // namespace test_free_mass
