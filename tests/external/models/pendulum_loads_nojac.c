/* The external functions of ext_pendulum.mbd, without their derivatives: the
   generated code then takes central differences of them. The prototypes come
   from the generated code (yamsc --external compiles this file against them). */
void tip_spring(const double* a, double* r) {
    r[0] = -a[2] * a[0] + 0.0 * a[1];
    r[1] = 0.0;
    r[2] = 0.0;
}
void damper(const double* a, double* r) {
    r[0] = 0.0;
    r[1] = -a[1] * a[0];
    r[2] = 0.0;
}
void push(const double* a, double* r) {
    r[0] = a[0] + a[1] + 0.0 * a[2];
}
