// `yamsc rotor-table`: the rotor block's table and interpolation as one C99
// file, compiled on its own with strict flags; its numbers equal the runtime's.
#include "embedded/support.hpp"

#include <yamsc/performance_table.hpp>

#include <doctest/doctest.h>

#include <sstream>

using namespace embedded_test;

TEST_CASE("yamsc rotor-table writes C99 whose coefficients equal the runtime's") {
    const std::string dir = scratch_dir("rotor_table");
    const std::string table = std::string(YAMSC_TEST_DATA_DIR) + "/rosco/Cp_Ct_Cq.NREL5MW.txt";
    REQUIRE(run(std::string(YAMSC_EXE) + " rotor-table " + table + " -o " + dir +
                "/nrel.c --prefix nrel > " + dir + "/log.txt 2>&1") == 0);
    write_file(dir + "/main.c", R"(#include <stdio.h>
double nrel_coefficient(int which, double tsr, double pitch_deg, double* d_tsr, double* d_pitch);
int main(void) {
    static const double points[][2] = {{7.5, 0.0}, {7.41, 0.3}, {4.99, 11.535}, {1.0, -7.0},
                                       {15.2, 31.0}, {9.87, 17.2}};
    int i, w;
    for (i = 0; i < 6; ++i)
        for (w = 0; w < 3; ++w) {
            double dt, dp;
            const double v = nrel_coefficient(w, points[i][0], points[i][1], &dt, &dp);
            printf("%.17g %.17g %.17g\n", v, dt, dp);
        }
    return 0;
}
)");
    const std::string cc =
        std::string(YAMSC_C_COMPILER) + " -std=c99 -pedantic -Wall -Wextra -Werror -O2 ";
    REQUIRE(run(cc + dir + "/nrel.c " + dir + "/main.c -o " + dir + "/prog -lm > " + dir +
                "/cc.txt 2>&1") == 0);
    REQUIRE(run(dir + "/prog > " + dir + "/out.txt") == 0);
    std::istringstream out(read_file(dir + "/out.txt"));
    const yamsc::runtime::PerformanceTable t = yamsc::runtime::read_performance_table(table);
    const double points[][2] = {{7.5, 0.0},  {7.41, 0.3},  {4.99, 11.535},
                                {1.0, -7.0}, {15.2, 31.0}, {9.87, 17.2}};
    for (const auto& p : points)
        for (const std::vector<double>* v : {&t.cp, &t.ct, &t.cq}) {
            const yamsc::runtime::Coefficient c = yamsc::runtime::interpolate(t, *v, p[0], p[1]);
            double value = 0, d_tsr = 0, d_pitch = 0;
            REQUIRE(static_cast<bool>(out >> value >> d_tsr >> d_pitch));
            CHECK(value == doctest::Approx(c.value).epsilon(1e-14));
            CHECK(d_tsr == doctest::Approx(c.d_tsr).epsilon(1e-13));
            CHECK(d_pitch == doctest::Approx(c.d_pitch).epsilon(1e-13));
        }
    // the table's design point: Cp(7.5, 0) = 0.465861
    std::istringstream first(read_file(dir + "/out.txt"));
    double cp = 0;
    first >> cp;
    CHECK(cp == 0.465861);
}
