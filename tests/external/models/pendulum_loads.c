/* The external functions of ext_pendulum.mbd, with their derivatives. The
   prototypes come from the generated code (yamsc --external compiles this file
   against them). */
void tip_spring(const double* a, double* r) {
    r[0] = -a[2] * a[0] + 0.0 * a[1];
    r[1] = 0.0;
    r[2] = 0.0;
}
void tip_spring_jacobian(const double* a, double* J) {
    for (int i = 0; i < 9; ++i) J[i] = 0.0;
    J[0] = -a[2];
    J[2] = -a[0];
}
void damper(const double* a, double* r) {
    r[0] = 0.0;
    r[1] = -a[1] * a[0];
    r[2] = 0.0;
}
void damper_jacobian(const double* a, double* J) {
    for (int i = 0; i < 6; ++i) J[i] = 0.0;
    J[2] = -a[1];
    J[3] = -a[0];
}
void push(const double* a, double* r) {
    r[0] = a[0] + a[1] + 0.0 * a[2];
}
void push_jacobian(const double* a, double* J) {
    J[0] = 1.0;
    J[1] = 1.0;
    J[2] = 0.0;
}
