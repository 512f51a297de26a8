// The tangent form of the derivatives (--jacobians tangent, chosen automatically
// from 25 DOFs on) computes the same functions as the unrolled form: every
// generated function of both forms of real models, compiled into one program,
// agrees at random points; the tangent rhs_jacobian agrees with central
// finite differences of the tangent rhs; and the automatic choice and the
// option's errors behave as documented (docs/cli.md, docs/benchmarks.md).
#include "test_files.hpp"

#include <doctest/doctest.h>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace {

std::string scratch(const std::string& name) {
    return test_support::scratch_dir("tangent_scratch", name);
}

int run(const std::string& command) {
    return test_support::exit_status(command);
}

using test_support::read_file;

std::string model_path(const std::string& name) {
    return std::string(YAMSC_SOURCE_DIR) + "/models/" + name + ".mbd";
}

/// An n-link 3D chain (2 DOFs a link) written by bench/write_chain.py.
std::string chain(int links, const std::string& dir) {
    const std::string path = dir + "/chain" + std::to_string(links) + ".mbd";
    REQUIRE(run(std::string(YAMSC_PYTHON) + " " + YAMSC_SOURCE_DIR + "/bench/write_chain.py " +
                std::to_string(links) + " " + path) == 0);
    return path;
}

// Evaluates every function of namespaces U (unrolled) and T (tangent) at random
// points and prints "<name> <max |u - t| / max(1, max |u|)>" per function, and
// "J_fd" for T's rhs_jacobian against central differences of T's rhs.
const char* driver = R"(#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>
#include "u.cpp"
#include "t.cpp"
using V = std::vector<double>;
static std::map<const char*, double> worst;
static void cmp(const char* name, const V& a, const V& b) {
    double scale = 1.0, diff = 0.0;
    for (double v : a) scale = std::max(scale, std::fabs(v));
    for (std::size_t i = 0; i < a.size(); ++i) diff = std::max(diff, std::fabs(a[i] - b[i]));
    worst[name] = std::max(worst[name], diff / scale);
}
int main() {
    constexpr int nq = U::nq, nu = U::nu, ny = U::ny, nx = 2 * nq;
    static_assert(T::nq == nq && T::nu == nu && T::ny == ny, "same model");
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> d(-0.8, 0.8);
    U::Params pu;
    T::Params pt;
    for (int point = 0; point < 3; ++point) {
        V q(nq), qd(nq), u(nu + 1), x(nx);
        for (int i = 0; i < nq; ++i) x[i] = q[i] = d(gen);
        for (int i = 0; i < nq; ++i) x[nq + i] = qd[i] = d(gen);
        for (int i = 0; i < nu; ++i) u[i] = d(gen);
        const double t = 0.3 * point;
        auto sized = [](int n) { return V(static_cast<std::size_t>(std::max(n, 1)), 0.0); };
        V a = sized(nq * nq), b = sized(nq * nq);
        U::mass_matrix(t, q.data(), u.data(), pu, a.data());
        T::mass_matrix(t, q.data(), u.data(), pt, b.data());
        cmp("mass_matrix", a, b);
        V fa = sized(nq), fb = sized(nq);
        U::forcing(t, q.data(), qd.data(), u.data(), pu, fa.data());
        T::forcing(t, q.data(), qd.data(), u.data(), pt, fb.data());
        cmp("forcing", fa, fb);
        V a1 = sized(nq * nq), a2 = sized(nq * nq), a3 = sized(nq * nu);
        V b1 = sized(nq * nq), b2 = sized(nq * nq), b3 = sized(nq * nu);
        U::jacobians(t, q.data(), qd.data(), u.data(), pu, a1.data(), a2.data(), a3.data());
        T::jacobians(t, q.data(), qd.data(), u.data(), pt, b1.data(), b2.data(), b3.data());
        cmp("dF_dq", a1, b1);
        cmp("dF_dqd", a2, b2);
        cmp("dF_du", a3, b3);
        V ya = sized(ny), yb = sized(ny);
        U::outputs(t, q.data(), qd.data(), u.data(), pu, ya.data());
        T::outputs(t, q.data(), qd.data(), u.data(), pt, yb.data());
        cmp("outputs", ya, yb);
        V xa = sized(nx), xb = sized(nx);
        U::rhs(t, x.data(), u.data(), pu, xa.data());
        T::rhs(t, x.data(), u.data(), pt, xb.data());
        cmp("rhs", xa, xb);
        V Ja = sized(nx * nx), Jb = sized(nx * nx), Jfd = sized(nx * nx);
        U::rhs_jacobian(t, x.data(), u.data(), pu, Ja.data());
        T::rhs_jacobian(t, x.data(), u.data(), pt, Jb.data());
        cmp("rhs_jacobian", Ja, Jb);
        for (int k = 0; k < nx; ++k) {
            const double h = 1e-6 * std::max(1.0, std::fabs(x[k]));
            V xp = x, xm = x, fp = sized(nx), fm = sized(nx);
            xp[k] += h;
            xm[k] -= h;
            T::rhs(t, xp.data(), u.data(), pt, fp.data());
            T::rhs(t, xm.data(), u.data(), pt, fm.data());
            for (int i = 0; i < nx; ++i) Jfd[i * nx + k] = (fp[i] - fm[i]) / (2 * h);
        }
        cmp("J_fd", Jfd, Jb);
        V M0a = sized(nq * nq), C0a = sized(nq * nq), K0a = sized(nq * nq), Q0a = sized(nq * nu);
        V M0b = sized(nq * nq), C0b = sized(nq * nq), K0b = sized(nq * nq), Q0b = sized(nq * nu);
        U::linear(q.data(), qd.data(), u.data(), pu, M0a.data(), C0a.data(), K0a.data(), Q0a.data());
        T::linear(q.data(), qd.data(), u.data(), pt, M0b.data(), C0b.data(), K0b.data(), Q0b.data());
        cmp("M0", M0a, M0b);
        cmp("C0", C0a, C0b);
        cmp("K0", K0a, K0b);
        cmp("Q0", Q0a, Q0b);
        V Aa = sized(nx * nx), Ba = sized(nx * nu), Ab = sized(nx * nx), Bb = sized(nx * nu);
        U::state_space(q.data(), qd.data(), u.data(), pu, Aa.data(), Ba.data());
        T::state_space(q.data(), qd.data(), u.data(), pt, Ab.data(), Bb.data());
        cmp("A", Aa, Ab);
        cmp("B", Ba, Bb);
        V Ca = sized(ny * nx), Da = sized(ny * nu), Cb = sized(ny * nx), Db = sized(ny * nu);
        U::output_matrices(q.data(), qd.data(), u.data(), pu, Ca.data(), Da.data());
        T::output_matrices(q.data(), qd.data(), u.data(), pt, Cb.data(), Db.data());
        cmp("C", Ca, Cb);
        cmp("D", Da, Db);
    }
    for (const auto& [name, value] : worst) std::printf("%s %.3e\n", name, value);
}
)";

/// Both forms of `model` compiled into the driver; the worst differences by function.
std::map<std::string, double> compare_forms(const std::string& model, const std::string& dir) {
    const std::string yamsc = YAMSC_EXE;
    REQUIRE(run(yamsc + " " + model + " -o " + dir + "/u.cpp --namespace U --jacobians unrolled") ==
            0);
    REQUIRE(run(yamsc + " " + model + " -o " + dir + "/t.cpp --namespace T --jacobians tangent") ==
            0);
    std::ofstream(dir + "/driver.cpp") << "#include <map>\n" << driver;
    REQUIRE(run(std::string(YAMSC_CXX_COMPILER) + " -std=c++17 -O1 -Wall -Wextra -Werror " + dir +
                "/driver.cpp -o " + dir + "/driver 2> " + dir + "/compile.log") == 0);
    REQUIRE(run(dir + "/driver > " + dir + "/out.txt") == 0);
    std::map<std::string, double> worst;
    std::istringstream out(read_file(dir + "/out.txt"));
    std::string name;
    double value = 0;
    while (out >> name >> value) worst[name] = value;
    return worst;
}

void check_agreement(const std::map<std::string, double>& worst) {
    REQUIRE(worst.size() == 17);
    for (const auto& [name, value] : worst) {
        INFO(name << ": " << value);
        // Central differences with h = 1e-6 carry ~1e-9 of truncation and rounding.
        CHECK(value <= (name == "J_fd" ? 1e-6 : 1e-11));
    }
}

} // namespace

TEST_CASE("the tangent form computes every function of the unrolled form") {
    for (const std::string name :
         {"double_pendulum", "heavy_top", "nrel5mw_land_2dof", "nrel5mw_spar_rigid"}) {
        CAPTURE(name);
        check_agreement(compare_forms(model_path(name), scratch(name)));
    }
    const std::string dir = scratch("chain4");
    check_agreement(compare_forms(chain(4, dir), dir));
}

TEST_CASE("the tangent form is chosen from 25 DOFs on, and explained when asked wrongly") {
    const std::string dir = scratch("auto");
    const std::string yamsc = YAMSC_EXE;
    // 12 links = 24 DOFs: unrolled; 13 links = 26 DOFs: tangent (internal mass_times).
    REQUIRE(run(yamsc + " " + chain(12, dir) + " -o " + dir + "/c12.cpp") == 0);
    REQUIRE(run(yamsc + " " + chain(13, dir) + " -o " + dir + "/c13.cpp") == 0);
    CHECK(read_file(dir + "/c12.cpp").find("mass_times(") == std::string::npos);
    CHECK(read_file(dir + "/c13.cpp").find("mass_times(") != std::string::npos);
    CHECK(read_file(dir + "/c13.cpp").find("--jacobians") ==
          std::string::npos); // auto: not recorded

    // Usage errors (exit 2) with a reason.
    const std::string err = dir + "/err.txt";
    CHECK(run(yamsc + " " + model_path("pendulum") + " -o " + dir +
              "/p.cpp --jacobians sideways 2> " + err) == 2);
    CHECK(read_file(err).find("--jacobians must be auto, unrolled or tangent") !=
          std::string::npos);
    CHECK(run(yamsc + " " + model_path("pendulum") + " -o " + dir +
              "/p.cpp --jacobians tangent --sensitivities g 2> " + err) == 2);
    CHECK(read_file(err).find("--sensitivities needs") != std::string::npos);
    std::ofstream(dir + "/approx.mbd") << "model approx_pendulum\n"
                                          "param g = 9.81\n"
                                          "dof theta\n"
                                          "gravity (0, 0, -g)\n"
                                          "rigid bob {\n    mass = 1\n    com = (0, 0, -1)\n}\n"
                                          "joint ground -> bob { rotate y theta }\n"
                                          "approx theta order 1\n";
    CHECK(run(yamsc + " " + dir + "/approx.mbd -o " + dir + "/a.cpp --jacobians tangent 2> " +
              err) == 2);
    CHECK(read_file(err).find("does not apply to a model with `approx`") != std::string::npos);
    // Reaction loads read q'' = M^-1 F: no tangent form either.
    std::ofstream(dir + "/reaction.mbd") << "model reaction_pendulum\n"
                                            "dof theta\n"
                                            "gravity (0, 0, -9.81)\n"
                                            "rigid bob { mass = 1; com = (0, 0, -1) }\n"
                                            "joint ground -> bob { rotate y theta }\n"
                                            "output Fz = reaction_force(bob).z\n";
    CHECK(run(yamsc + " " + dir + "/reaction.mbd -o " + dir + "/r.cpp --jacobians tangent 2> " +
              err) == 2);
    CHECK(read_file(err).find("outputs that read accelerations") != std::string::npos);
}
