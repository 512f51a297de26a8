// Simulates the generated mast with the runtime's RK4 for one period of its
// mode and prints the frequency the generated equations give; exits 1 when
// the motion does not come back to its start after that period.
#include "mast_model.hpp"

#include <yamsc/rk4.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
    const mast::Params params;
    double q[mast::nq] = {0.0}, qd[mast::nq] = {0.0}, M[mast::nq * mast::nq], F[mast::nq];
    q[0] = 0.01;
    mast::Model::mass_matrix(0.0, q, nullptr, params, M);
    mast::Model::forcing(0.0, q, qd, nullptr, params, F);
    const double omega = std::sqrt(-F[0] / (q[0] * M[0]));
    std::printf("omega %.6f\n", omega);

    const double period = 2 * std::acos(-1.0) / omega;
    const std::vector<double> x0 = {0.01, 0.0}, no_inputs;
    std::vector<double> x_end;
    auto view = yamsc::runtime::from_generated<mast::Model>(params);
    yamsc::runtime::simulate_rk4(view, x0, no_inputs, period, period / 2000,
                                 [&](double, const double* x) {
                                     x_end.assign(x, x + 2);
                                     return true;
                                 });
    const double drift = std::fabs(x_end[0] - x0[0]) / x0[0];
    std::printf("after one period q = %.9f (relative drift %.2e)\n", x_end[0], drift);
    return drift < 1e-6 ? 0 : 1;
}
