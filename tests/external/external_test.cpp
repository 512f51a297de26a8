// External functions (`external ...`, --external): the user's C loads of
// tests/external/models/ext_pendulum.mbd called by the compiled model. The
// linear model is the same with and without the user's derivatives, matches
// the closed form, the Jacobians equal finite differences of rhs and forcing,
// and every error is located.
#include "analysis/loaded_model.hpp"
#include "codegen/routines.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace {

using test_support::exit_status;
using test_support::read_file;
using test_support::scratch_dir;
using test_support::write_file;

const std::string models = std::string(YAMSC_SOURCE_DIR) + "/tests/external/models/";
const std::string model = models + "ext_pendulum.mbd";
const std::string with_jacobians = models + "pendulum_loads.c";
const std::string without_jacobians = models + "pendulum_loads_nojac.c";

struct Run {
    int status = -1;
    std::string out, err;
};

Run run_yamsc(const std::string& args) {
    const std::string dir = std::string(YAMSC_TEST_BINARY_DIR);
    Run r;
    r.status = exit_status(std::string(YAMSC_EXE) + " " + args + " > " + dir +
                           "/external_out.txt 2> " + dir + "/external_err.txt");
    r.out = read_file(dir + "/external_out.txt");
    r.err = read_file(dir + "/external_err.txt");
    return r;
}

/// The numbers of a JSON array or matrix after `"key":`, flattened.
std::vector<double> numbers_of(const std::string& json, const std::string& key) {
    const auto at = json.find("\"" + key + "\":");
    REQUIRE(at != std::string::npos);
    std::size_t i = at + key.size() + 3;
    int depth = 0;
    std::vector<double> out;
    std::string number;
    for (; i < json.size(); ++i) {
        const char c = json[i];
        if (c == '[') ++depth;
        if (c == ']' || c == ',') {
            if (!number.empty()) out.push_back(std::stod(number));
            number.clear();
        }
        if (c == ']' && --depth == 0) break;
        if (c != '[' && c != ']' && c != ',') number += c;
    }
    return out;
}

double frequency(const std::string& json) {
    const auto at = json.find("\"freq_hz\":");
    REQUIRE(at != std::string::npos);
    return std::stod(json.substr(at + 10));
}

void check_close(const std::vector<double>& a, const std::vector<double>& b, double rel,
                 double abs_floor = 1e-12) {
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        CHECK(std::fabs(a[i] - b[i]) <= rel * std::max(std::fabs(b[i]), abs_floor / rel));
}

} // namespace

TEST_CASE("lin: the user's derivatives and central differences give the same linear model, "
          "and the closed form") {
    const Run exact = run_yamsc("lin " + model + " --external " + with_jacobians + " --json");
    const Run differences =
        run_yamsc("lin " + model + " --external " + without_jacobians + " --json");
    REQUIRE(exact.status == 0);
    REQUIRE(differences.status == 0);
    for (const char* key : {"M0", "C0", "K0", "Q0", "A", "B"})
        check_close(numbers_of(differences.out, key), numbers_of(exact.out, key), 1e-6);
    // Without the derivatives the command says so, once per function.
    CHECK(differences.err.find("tip_spring: derivatives by central differences") !=
          std::string::npos);
    CHECK(exact.err.find("central differences") == std::string::npos);
    // K = m g L + k L^2, C = c, M = m L^2, Q = d(P + tau)/dtau = 1 (through the function).
    const double m = 2.0, L = 1.5, g = 9.81, k = 30.0, c = 0.4;
    CHECK(numbers_of(exact.out, "K0")[0] == doctest::Approx(m * g * L + k * L * L).epsilon(1e-12));
    CHECK(numbers_of(exact.out, "C0")[0] == doctest::Approx(c).epsilon(1e-12));
    CHECK(numbers_of(exact.out, "Q0")[0] == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(frequency(exact.out) ==
          doctest::Approx(std::sqrt(g / L + k / m) / (2 * M_PI)).epsilon(1e-6));
}

TEST_CASE("trim: a constant external torque gives the static deflection asin(P / (m g L))") {
    const Run r =
        run_yamsc("trim " + model + " --external " + with_jacobians + " --set k=0,P=5 --json");
    REQUIRE(r.status == 0);
    CHECK(numbers_of(r.out, "q")[0] ==
          doctest::Approx(std::asin(5.0 / (2.0 * 9.81 * 1.5))).epsilon(1e-9));
}

TEST_CASE("the compiled Jacobians with externals equal finite differences of rhs and forcing") {
    // One implementation per process: the functions bind by name in the global
    // scope (docs/cli.md); the central differences are checked in compiled code below.
    for (const std::string& source : {with_jacobians}) {
        CAPTURE(source);
        std::ostringstream err;
        auto loaded = yamsc::analysis::load(model, {{"P", 0, 0.5}, {"c", 0, 0.7}}, "", false, err,
                                            {}, yamsc::codegen::abi_routines(), source);
        REQUIRE_MESSAGE(loaded, err.str());
        const yamsc::runtime::ModelView& v = loaded->view;
        REQUIRE(v.nq == 1);
        REQUIRE(v.nu == 1);
        const double t = 0.3;
        std::vector<double> x{0.4, -0.9}, u{0.25}, J(4);
        v.rhs_jacobian(t, x.data(), u.data(), J.data());
        for (int j = 0; j < 2; ++j) {
            const double h = 1e-6;
            std::vector<double> xp = x, xm = x, fp(2), fm(2);
            xp[j] += h;
            xm[j] -= h;
            v.rhs(t, xp.data(), u.data(), fp.data());
            v.rhs(t, xm.data(), u.data(), fm.data());
            for (int i = 0; i < 2; ++i)
                CHECK(J[i * 2 + j] == doctest::Approx((fp[i] - fm[i]) / (2 * h)).epsilon(1e-6));
        }
        double dF_dq = 0, dF_dqd = 0, dF_du = 0;
        v.jacobians(t, x.data(), x.data() + 1, u.data(), &dF_dq, &dF_dqd, &dF_du);
        auto F = [&](double q, double qd, double tau) {
            double f = 0;
            v.forcing(t, &q, &qd, &tau, &f);
            return f;
        };
        const double h = 1e-6;
        CHECK(dF_dq ==
              doctest::Approx((F(x[0] + h, x[1], u[0]) - F(x[0] - h, x[1], u[0])) / (2 * h))
                  .epsilon(1e-6));
        CHECK(dF_dqd ==
              doctest::Approx((F(x[0], x[1] + h, u[0]) - F(x[0], x[1] - h, u[0])) / (2 * h))
                  .epsilon(1e-6));
        CHECK(dF_du == doctest::Approx(1.0).epsilon(1e-6));
        // F = -m g L sin th + (the spring's moment) - c th' + P + tau, exactly.
        const double th = x[0], L = 1.5;
        CHECK(F(th, x[1], u[0]) ==
              doctest::Approx(-2.0 * 9.81 * L * std::sin(th) -
                              30.0 * L * L * std::sin(th) * std::cos(th) - 0.7 * x[1] + 0.5 + u[0])
                  .epsilon(1e-12));
    }
}

TEST_CASE("errors of external functions are located and end with exit status 1 or 2") {
    const std::string dir = scratch_dir("external", "errors");
    SUBCASE("no --external") {
        const Run r = run_yamsc("lin " + model);
        CHECK(r.status == 1);
        CHECK(r.err.find("ext_pendulum.mbd:13:") != std::string::npos);
        CHECK(r.err.find("'tip_spring' has no implementation") != std::string::npos);
    }
    SUBCASE("a function missing from the source") {
        write_file(dir + "/partial.c", "void tip_spring(const double* a, double* r) "
                                       "{ r[0] = a[0]; r[1] = r[2] = 0; }\n"
                                       "void push(const double* a, double* r) { r[0] = a[0]; }\n");
        const Run r =
            run_yamsc("sim " + model + " --tmax 0.1 --dt 0.01 --external " + dir + "/partial.c");
        CHECK(r.status == 1);
        CHECK(r.err.find("ext_pendulum.mbd:14:") != std::string::npos);
        CHECK(r.err.find("'damper' is not in") != std::string::npos);
    }
    SUBCASE("a wrong signature is a compile error") {
        write_file(dir + "/wrong.c", "void tip_spring(double* a, double* r) { r[0] = a[0]; }\n");
        const Run r = run_yamsc("lin " + model + " --external " + dir + "/wrong.c");
        CHECK(r.status == 1);
        CHECK(r.err.find("wrong.c:1:") != std::string::npos);
        CHECK(r.err.find("does not compile against the model's prototypes") != std::string::npos);
    }
    SUBCASE("a result that is not finite names the function, its declaration and the arguments") {
        std::string source = read_file(without_jacobians);
        source = "#include <math.h>\n" +
                 test_support::replace_all(source, "r[0] = a[0] + a[1]",
                                           "r[0] = a[1] > 1 ? NAN : a[0] + a[1]");
        write_file(dir + "/nan.c", source);
        const Run r = run_yamsc("sim " + model + " --tmax 0.1 --dt 0.01 --u tau=2 --external " +
                                dir + "/nan.c");
        CHECK(r.status == 1);
        CHECK(r.err.find("ext_pendulum.mbd:15:24: external function 'push' returned a value that "
                         "is not finite, result[0] = nan; its arguments were (0, 2, 0)") !=
              std::string::npos);
    }
    SUBCASE("--external for a model without externals, and an output over it, are usage errors") {
        CHECK(run_yamsc("lin " + std::string(YAMSC_SOURCE_DIR) +
                        "/models/pendulum.mbd --external " + with_jacobians)
                  .status == 2);
        write_file(dir + "/loads.c", read_file(with_jacobians));
        const Run r = run_yamsc("sim " + model + " --tmax 0.1 --dt 0.01 --external " + dir +
                                "/loads.c -o " + dir + "/loads.c");
        CHECK(r.status == 2);
        CHECK(read_file(dir + "/loads.c") == read_file(with_jacobians));
    }
    SUBCASE("--lang c, --jacobians tangent and --sensitivities refuse models with externals") {
        const Run c = run_yamsc(model + " --lang c -o " + dir + "/m.c");
        CHECK(c.status == 1);
        CHECK(c.err.find("not supported in --lang c yet") != std::string::npos);
        CHECK(run_yamsc(model + " --jacobians tangent -o " + dir + "/m.cpp").status == 2);
        CHECK(run_yamsc(model + " --sensitivities k -o " + dir + "/m.cpp").status == 2);
    }
}

TEST_CASE("the generated C++ declares the functions and compiles with the user's loads") {
    const std::string dir = scratch_dir("external", "generated");
    REQUIRE(run_yamsc(model + " -o " + dir + "/m.cpp --header " + dir + "/m.hpp").status == 0);
    const std::string header = read_file(dir + "/m.hpp");
    CHECK(header.find("void tip_spring(const double* args, double* result);") != std::string::npos);
    CHECK(header.find("void damper_jacobian(const double* args, double* d_result_d_args);") !=
          std::string::npos);
    CHECK(header.find("tip_spring_jacobian when linked, else central differences") !=
          std::string::npos);
    // rhs against the closed form, rhs_jacobian against central differences of
    // rhs: with the user's derivatives and without them (central differences of
    // the functions inside the generated code).
    write_file(dir + "/main.cpp", R"(#include "m.hpp"
#include <cmath>
#include <cstdio>
int main() {
    ext_pendulum::Params p;
    p.P = 0.5;
    double x[2] = {0.2, 0.1}, u[1] = {0.3}, xdot[2], J[4];
    ext_pendulum::rhs(0.7, x, u, p, xdot);
    const double F = -p.m * p.g * p.L * std::sin(0.2) -
                     p.k * p.L * p.L * std::sin(0.2) * std::cos(0.2) - p.c * 0.1 + 0.5 + 0.3;
    int failures = std::fabs(xdot[1] - F / (p.m * p.L * p.L)) < 1e-12 ? 0 : 1;
    ext_pendulum::rhs_jacobian(0.7, x, u, p, J);
    for (int j = 0; j < 2; ++j) {
        const double h = 1e-6;
        double xp[2] = {x[0], x[1]}, xm[2] = {x[0], x[1]}, fp[2], fm[2];
        xp[j] += h;
        xm[j] -= h;
        ext_pendulum::rhs(0.7, xp, u, p, fp);
        ext_pendulum::rhs(0.7, xm, u, p, fm);
        for (int i = 0; i < 2; ++i) {
            const double fd = (fp[i] - fm[i]) / (2 * h);
            if (std::fabs(J[i * 2 + j] - fd) > 1e-6 * std::fmax(1.0, std::fabs(fd))) {
                std::printf("J[%d][%d] = %.12g, differences %.12g\n", i, j, J[i * 2 + j], fd);
                ++failures;
            }
        }
    }
    return failures;
}
)");
    const std::string cc = std::string(YAMSC_C_COMPILER), cxx = std::string(YAMSC_CXX_COMPILER);
    for (const std::string& loads : {with_jacobians, without_jacobians}) {
        CAPTURE(loads);
        CHECK(exit_status("cd " + dir + " && " + cc + " -c -o loads.o " + loads + " && " + cxx +
                          " -std=c++17 -Wall -Wextra -Werror -pedantic main.cpp m.cpp loads.o -o "
                          "run && ./run") == 0);
    }
}

TEST_CASE("--external takes a library built beforehand") {
    const std::string dir = scratch_dir("external", "library");
    REQUIRE(exit_status(std::string(YAMSC_C_COMPILER) + " -shared -fPIC -O2 -o " + dir +
                        "/libloads.so " + with_jacobians) == 0);
    const Run r = run_yamsc("lin " + model + " --external " + dir + "/libloads.so --json");
    REQUIRE(r.status == 0);
    CHECK(numbers_of(r.out, "K0")[0] ==
          doctest::Approx(2.0 * 9.81 * 1.5 + 30.0 * 1.5 * 1.5).epsilon(1e-12));
    CHECK(r.err.find("central differences") == std::string::npos);
    CHECK(run_yamsc("lin " + model + " --external " + dir + "/missing.so").status == 1);
}

TEST_CASE("check lists the external functions: what they load, their arguments and results") {
    std::ostringstream text, json, err;
    REQUIRE(yamsc::driver::check({model, false}, text, err) == 0);
    CHECK(text.str().find("externals (3):\n"
                          "  tip_spring(3 args -> 3 results: force on link)\n"
                          "  damper(2 args -> 3 results: torque on link)\n"
                          "  push(3 args -> 1 result: genforce th)\n") != std::string::npos);
    REQUIRE(yamsc::driver::check({model, true}, json, err) == 0);
    CHECK(json.str().find("\"externals\":[{\"name\":\"tip_spring\",\"loads\":\"force\",\"on\":"
                          "[\"link\"],\"arguments\":3,\"results\":3,\"jacobian\":true},") !=
          std::string::npos);
    CHECK(json.str().find("{\"name\":\"push\",\"loads\":\"genforce\",\"on\":[\"th\"],"
                          "\"arguments\":3,\"results\":1,\"jacobian\":true}]}") !=
          std::string::npos);
}
