// The helper routines generated code calls (compiler/codegen/helpers/*.inc)
// are real source files: each compiled on its own, as strict C99 and as C++17,
// into a small program whose numbers are checked here: an LDL^T solve of a
// symmetric positive definite system, and one RK4 step of x' = -k x against
// the exact step of RK4 (the Taylor polynomial of exp to 4th order) and exp.
#include "embedded/support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <vector>

using namespace embedded_test;

namespace {

const std::string helpers_dir = std::string(YAMSC_SOURCE_DIR) + "/compiler/codegen/helpers";

// The program: the .inc files with the names they leave open defined as
// generated code defines them (double, a parameter struct, the state's size).
const char* driver_text = R"(#include <stdio.h>

typedef double yamsc_real;
typedef double yamsc_api_real;
#define YAMSC_LINKAGE static
#define YAMSC_LITERAL(v) v
#define YAMSC_NX 2
#define YAMSC_NX_ARRAY 2
typedef struct {
    double k[2];
} yamsc_params;

#include "ldlt.inc"

static void rhs(yamsc_api_real t, const yamsc_api_real* x, const yamsc_api_real* u,
                const yamsc_params* p, yamsc_api_real* xdot) {
    (void)t;
    (void)u;
    xdot[0] = -p->k[0] * x[0];
    xdot[1] = -p->k[1] * x[1];
}

#include "rk4.inc"

int main(void) {
    /* A = [4 1 2; 1 3 0; 2 0 5] (only the lower triangle is read), X = [1 -2; 2 0.5; -1 3]. */
    double A[9] = {4, -99, -99, 1, 3, -99, 2, 0, 5};
    double B[6] = {4, -1.5, 7, -0.5, -3, 11};
    double x[2] = {1.0, 2.0};
    const double u[1] = {0.0};
    yamsc_params p;
    int i;
    p.k[0] = 1.0;
    p.k[1] = 3.0;
    ldlt_factor(A, 3);
    ldlt_solve(A, 3, B, 2);
    for (i = 0; i < 6; ++i) printf("%.17g\n", B[i]);
    rk4_step(0.0, 0.1, x, u, &p);
    printf("%.17g\n%.17g\n", x[0], x[1]);
    return 0;
}
)";

std::vector<double> numbers(const std::string& text) {
    std::istringstream in(text);
    std::vector<double> out;
    for (double v; in >> v;) out.push_back(v);
    return out;
}

void check_program(const std::string& compiler, const std::string& flags, const std::string& name) {
    const std::string dir = scratch_dir("helpers_" + name);
    write_file(dir + "/driver.c", driver_text);
    const std::string exe = dir + "/driver";
    const std::string command = compiler + " " + flags + " -Wall -Wextra -Werror -I" + helpers_dir +
                                " " + dir + "/driver.c -o " + exe + " -lm > " + dir +
                                "/cc.log 2>&1";
    REQUIRE_MESSAGE(run(command) == 0, command, "\n", read_file(dir + "/cc.log"));
    REQUIRE(run(exe + " > " + dir + "/out.txt") == 0);
    const std::vector<double> v = numbers(read_file(dir + "/out.txt"));
    REQUIRE(v.size() == 8);
    // A X = B with X = [1 -2; 2 0.5; -1 3].
    const double X[6] = {1, -2, 2, 0.5, -1, 3};
    for (int i = 0; i < 6; ++i) CHECK(v[i] == doctest::Approx(X[i]).epsilon(1e-14));
    // RK4 on a linear ODE is exact to the Taylor polynomial of exp(-k h) to 4th
    // order; its error against exp is then the 5th-order term (not zero).
    const double h = 0.1, k[2] = {1.0, 3.0}, x0[2] = {1.0, 2.0};
    for (int i = 0; i < 2; ++i) {
        const double z = -k[i] * h;
        const double taylor = 1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24;
        CHECK(v[6 + i] == doctest::Approx(x0[i] * taylor).epsilon(1e-15));
        const double error = std::fabs(v[6 + i] - x0[i] * std::exp(z));
        const double fifth = x0[i] * std::fabs(z * z * z * z * z) / 120;
        CHECK(error == doctest::Approx(fifth).epsilon(0.2));
    }
}

} // namespace

TEST_CASE("helpers: ldlt.inc and rk4.inc compile as strict C99 and solve correctly") {
    check_program(YAMSC_C_COMPILER, "-std=c99 -pedantic -x c", "c99");
}

TEST_CASE("helpers: ldlt.inc and rk4.inc compile as C++17 and solve correctly") {
    check_program(YAMSC_CXX_COMPILER, "-std=c++17 -pedantic -x c++", "cxx17");
}
