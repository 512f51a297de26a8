/* Uses the generated C pendulum without the runtime, as a controller would:
 * prints the small-swing frequency from M and dF/dtheta and exits 1 unless it is
 * sqrt(g / L). */
#include "pendulum.h"

#include <math.h>
#include <stdio.h>

int main(void) {
    const pendulum_params p = pendulum_default_params();
    const double h = 1e-6;
    double q[1] = {h}, qd[1] = {0.0}, M[1], F[1];
    pendulum_mass_matrix(q, &p, M);
    pendulum_forcing(0.0, q, qd, 0, &p, F);
    const double omega = sqrt(-F[0] / (h * M[0]));
    printf("omega %.6f\n", omega);
    return fabs(omega - sqrt(p.g / p.L)) < 1e-6 ? 0 : 1;
}
