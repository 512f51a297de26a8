// The emitted linear_sensitivities (yamsc --sensitivities) against central
// finite differences in the parameters of the emitted linear(), at random
// operating points away from equilibrium (q0, q0' nonzero, so that C0 and the
// q''0 terms of K0 matter); exact zeros where a matrix does not depend on a
// parameter; and no trace of the routine when the option names nothing.
#include "generated_model.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <sstream>
#include <utility>

using namespace linear_test;

namespace {

// Prints the sizes and the default parameters, reads the indices of the chosen
// parameters, then points (p, q0, qd0, u0), and prints linear() and
// linear_sensitivities at each point, and fourth-order
// central differences of linear() in each chosen parameter: with a relative
// step of 1e-3 their truncation error is about 1e-12 and their rounding error
// about eps / 1e-3 of the matrix (second-order differences cannot resolve
// small sensitivities of large matrices to 1e-7).
const char* driver_text = R"(#include "model.cpp"
#include <cmath>
#include <cstdio>
#include <vector>

using Model = NS::Model;
static const int nq = Model::nq, nu = Model::nu, np = Model::np, nn = nq * nq;

static void print(int k, const char* name, const std::vector<double>& v) {
    std::printf("%d %s", k, name);
    for (double x : v) std::printf(" %.17g", x);
    std::printf("\n");
}

static double step(double x) { return 1e-3 * (std::fabs(x) > 1 ? std::fabs(x) : 1.0); }

struct Linear { std::vector<double> M0, C0, K0, Q0; };

static Linear linear(const std::vector<double>& pa, const std::vector<double>& q0,
                     const std::vector<double>& qd0, const std::vector<double>& u0) {
    Linear l{std::vector<double>(nn), std::vector<double>(nn), std::vector<double>(nn),
             std::vector<double>(nq * nu + 1)};
    Model::linear(q0.data(), qd0.data(), u0.data(), Model::params_from_array(pa.data()),
                  l.M0.data(), l.C0.data(), l.K0.data(), l.Q0.data());
    return l;
}

int main() {
    std::vector<double> pa(np + 1), q0(nq), qd0(nq), u0(nu + 1);
    Model::params_to_array(Model::Params{}, pa.data());
    print(-1, "sizes", {double(nq), double(nu), double(np)});
    print(-1, "defaults", std::vector<double>(pa.begin(), pa.begin() + np));
    int k = 0;
    if (std::scanf("%d", &k) != 1) return 0;
    std::vector<int> index(k);
    for (int j = 0; j < k; ++j) if (std::scanf("%d", &index[j]) != 1) return 1;
    for (int point = 0;; ++point) {
        for (int i = 0; i < np; ++i) if (std::scanf("%lf", &pa[i]) != 1) return 0;
        for (int i = 0; i < nq; ++i) if (std::scanf("%lf", &q0[i]) != 1) return 1;
        for (int i = 0; i < nq; ++i) if (std::scanf("%lf", &qd0[i]) != 1) return 1;
        for (int i = 0; i < nu; ++i) if (std::scanf("%lf", &u0[i]) != 1) return 1;
        std::vector<double> dM(k * nn), dC(k * nn), dK(k * nn), dQ(k * nq * nu + 1);
        Model::linear_sensitivities(q0.data(), qd0.data(), u0.data(),
                                    Model::params_from_array(pa.data()), dM.data(), dC.data(),
                                    dK.data(), dQ.data());
        dQ.resize(k * nq * nu);
        print(point, "dM0", dM); print(point, "dC0", dC); print(point, "dK0", dK);
        print(point, "dQ0", dQ);
        const Linear base = linear(pa, q0, qd0, u0);
        print(point, "M0", base.M0); print(point, "C0", base.C0); print(point, "K0", base.K0);
        print(point, "Q0", std::vector<double>(base.Q0.begin(), base.Q0.end() - 1));
        std::vector<double> fM, fC, fK, fQ;
        for (int j = 0; j < k; ++j) {
            const double h = step(pa[index[j]]);
            Linear l[4]; // at p_j - 2h, p_j - h, p_j + h, p_j + 2h
            for (int s = 0; s < 4; ++s) {
                std::vector<double> ps = pa;
                ps[index[j]] += h * (s < 2 ? s - 2 : s - 1);
                l[s] = linear(ps, q0, qd0, u0);
            }
            auto d = [&](std::vector<double> Linear::*m, int i) {
                return (8 * ((l[2].*m)[i] - (l[1].*m)[i]) - ((l[3].*m)[i] - (l[0].*m)[i])) /
                       (12 * h);
            };
            for (int i = 0; i < nn; ++i) {
                fM.push_back(d(&Linear::M0, i));
                fC.push_back(d(&Linear::C0, i));
                fK.push_back(d(&Linear::K0, i));
            }
            for (int i = 0; i < nq * nu; ++i) fQ.push_back(d(&Linear::Q0, i));
        }
        print(point, "dM0_fd", fM); print(point, "dC0_fd", fC); print(point, "dK0_fd", fK);
        print(point, "dQ0_fd", fQ);
        std::fflush(stdout);
    }
}
)";

using test_support::replace_all;

/// A model compiled with --sensitivities into the program above.
struct SensitivityModel {
    std::string dir, exe, source;
    std::vector<int> index; // of the chosen parameters, in the model's order
    int nq = 0, nu = 0, np = 0;
    std::vector<double> defaults;

    SensitivityModel(const std::string& model, const std::string& ns, const std::string& names,
                     const std::vector<int>& parameter_index)
        : dir(scratch_dir("sens_" + ns)), index(parameter_index) {
        const std::string path = std::string(YAMSC_SOURCE_DIR) + "/" + model;
        const std::string yamsc = std::string(YAMSC_EXE) + " " + path + " --sensitivities " + names;
        REQUIRE_MESSAGE(run(yamsc + " -o " + dir + "/model.cpp 2>" + dir + "/yamsc.log"),
                        read_file(dir + "/yamsc.log"));
        source = read_file(dir + "/model.cpp");
        // The C output must compile cleanly with the routine too.
        REQUIRE_MESSAGE(run(yamsc + " -o " + dir + "/model.c"), "yamsc --lang c failed");
        REQUIRE_MESSAGE(run(std::string(YAMSC_C_COMPILER) +
                            " -std=c99 -pedantic -Wall -Wextra -Werror -c " + dir + "/model.c -o " +
                            dir + "/model_c.o > " + dir + "/cc.log 2>&1"),
                        read_file(dir + "/cc.log"));
        write_file(dir + "/driver.cpp", replace_all(driver_text, "NS::", ns + "::"));
        exe = dir + "/driver";
        REQUIRE_MESSAGE(run(std::string(YAMSC_CXX_COMPILER) +
                            " -std=c++17 -O1 -Wall -Wextra -Werror -I" + dir + " " + dir +
                            "/driver.cpp -o " + exe + " > " + dir + "/compile.log 2>&1"),
                        read_file(dir + "/compile.log"));
        write_file(dir + "/none.txt", "");
        REQUIRE(run(exe + " < " + dir + "/none.txt > " + dir + "/head.txt"));
        Values head = parse_printed(read_file(dir + "/head.txt"))[-1];
        REQUIRE(head["sizes"].size() == 3);
        nq = static_cast<int>(head["sizes"][0]);
        nu = static_cast<int>(head["sizes"][1]);
        np = static_cast<int>(head["sizes"][2]);
        defaults = head["defaults"];
    }

    std::vector<Values> evaluate(const std::vector<Point>& points) const {
        std::ostringstream in;
        in.precision(17);
        in << index.size();
        for (int i : index) in << " " << i;
        in << "\n";
        for (const Point& pt : points) {
            for (const auto* v : {&pt.p, &pt.q, &pt.qd, &pt.u})
                for (double x : *v) in << x << " ";
            in << "\n";
        }
        write_file(dir + "/points.txt", in.str());
        REQUIRE(run(exe + " < " + dir + "/points.txt > " + dir + "/values.txt"));
        std::map<int, Values> all = parse_printed(read_file(dir + "/values.txt"));
        std::vector<Values> out;
        for (std::size_t k = 0; k < points.size(); ++k) out.push_back(all[static_cast<int>(k)]);
        return out;
    }
};

/// The differences between the analytic derivatives `a` and the finite
/// differences `b`, blocks of `block` entries (block j: d/dp_j with p_j =
/// `p[j]`), for a matrix whose value at the point is `base`. A block is
/// significant when p_j dX/dp_j reaches 1e-5 of X: it is compared relative to
/// its own largest entry (the derivatives in different parameters have
/// unrelated scales). A smaller one is near what the differences resolve
/// (their rounding error is about 1e-13 of X in these units) and is compared
/// in the same normalised units, |p_j (a - b)| / |X|.
struct Differences {
    double significant = 0, negligible = 0;
    int significant_blocks = 0;

    void add(const std::vector<double>& a, const std::vector<double>& b,
             const std::vector<double>& base, std::size_t block, const std::vector<double>& p) {
        REQUIRE(a.size() == b.size());
        REQUIRE(a.size() == block * p.size());
        double x = 0;
        for (double v : base) x = std::max(x, std::fabs(v));
        for (std::size_t j = 0; j < p.size(); ++j) {
            const double s = std::max(std::fabs(p[j]), 1e-3);
            double largest = 0, worst = 0;
            for (std::size_t i = j * block; i < (j + 1) * block; ++i) {
                largest = std::max(largest, std::fabs(a[i]));
                worst = std::max(worst, std::fabs(a[i] - b[i]));
            }
            if (largest * s > 1e-5 * x) {
                significant = std::max(significant, worst / largest);
                ++significant_blocks;
            } else if (worst > 0) {
                negligible = std::max(negligible, worst * s / x);
            }
        }
    }
};

double largest(const std::vector<double>& v, std::size_t first, std::size_t count) {
    double m = 0;
    for (std::size_t i = first; i < first + count; ++i) m = std::max(m, std::fabs(v[i]));
    return m;
}

struct Case {
    const char* model;
    const char* ns;
    const char* names;      // as given to --sensitivities
    std::vector<int> index; // the same parameters by index in the model
    std::vector<double> p;  // parameter values around which to draw
    double q_range, rate_range, input_scale;
};

std::vector<Point> random_points(const Case& c, int nq, int nu, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), factor(0.8, 1.25);
    std::vector<Point> points;
    for (int k = 0; k < count; ++k) {
        Point p;
        for (double d : c.p) p.p.push_back(d * factor(rng));
        for (int i = 0; i < nq; ++i) p.q.push_back(c.q_range * unit(rng));
        for (int i = 0; i < nq; ++i) p.qd.push_back(c.rate_range * unit(rng));
        for (int i = 0; i < nu; ++i) p.u.push_back(c.input_scale * unit(rng));
        points.push_back(p);
    }
    return points;
}

} // namespace

TEST_CASE("linear_sensitivities equals central differences of linear in the parameters") {
    const double deg = std::acos(-1.0) / 180;
    const Case cases[] = {
        // Not in declaration order: block j follows the command line.
        {"models/double_pendulum.mbd",
         "double_pendulum",
         "m2,g,L1,c,k,m1,L2",
         {1, 4, 2, 6, 5, 0, 3},
         {2.0, 1.0, 1.0, 0.8, 9.81, 5.0, 0.1},
         2.5,
         2,
         5},
        // Tower-top masses and inertias, tilt, gravity, tower length.
        {"models/nrel5mw_land_2dof.mbd",
         "nrel5mw_land_2dof",
         "M_N,J_yN,M_R,J_oR,theta_t,g,L_T",
         {3, 6, 7, 11, 2, 0, 1},
         {9.807, 87.6, 5 * deg, 2.4e5, 1.9, 1.75, 1.01e6, 1.1e5, -5.0, 2.4, 3.86e7, 1.92e7},
         1.0,
         1,
         1e6},
        // The rotor speed: centrifugal stiffening and softening in K0 (M0, C0
        // and Q0 of the blade do not depend on these parameters).
        {"models/nrel5mw_blade.mbd",
         "nrel5mw_blade",
         "Omega,r_hub,L_B",
         {0, 1, 2},
         {1.2, 1.5, 61.5},
         2.0,
         2,
         1e4},
    };
    for (const Case& c : cases) {
        const std::string model_name = c.model;
        CAPTURE(model_name);
        SensitivityModel m(c.model, c.ns, c.names, c.index);
        REQUIRE(m.source.find("linear_sensitivities") != std::string::npos);
        // The values drawn around are the defaults (but a spinning blade).
        REQUIRE(m.np == static_cast<int>(c.p.size()));
        for (std::size_t i = 0; i < c.p.size(); ++i)
            if (m.defaults[i] != 0) CHECK(std::fabs(c.p[i] / m.defaults[i] - 1) < 1e-12);
        const int nq = m.nq, nu = m.nu;
        const std::size_t nn = static_cast<std::size_t>(nq * nq);
        const std::vector<Point> points = random_points(c, nq, nu, 4, 7);
        const std::vector<Values> values = m.evaluate(points);
        Differences dM, dC, dK, dQ;
        double largest_dK_chain = 0;
        for (std::size_t k = 0; k < points.size(); ++k) {
            Values v = values[k];
            std::vector<double> p;
            for (int i : c.index) p.push_back(points[k].p[static_cast<std::size_t>(i)]);
            dM.add(v["dM0"], v["dM0_fd"], v["M0"], nn, p);
            dC.add(v["dC0"], v["dC0_fd"], v["C0"], nn, p);
            dK.add(v["dK0"], v["dK0_fd"], v["K0"], nn, p);
            dQ.add(v["dQ0"], v["dQ0_fd"], v["Q0"], static_cast<std::size_t>(nq * nu), p);
            // The damping coefficient enters K0 only through q''0.
            if (model_name == "models/double_pendulum.mbd")
                largest_dK_chain = std::max(largest_dK_chain, largest(v["dK0"], 3 * nn, nn));
        }
        const std::pair<const char*, const Differences*> matrices[] = {
            {"dM0", &dM}, {"dC0", &dC}, {"dK0", &dK}, {"dQ0", &dQ}};
        for (const auto& [name, d] : matrices) {
            MESSAGE(model_name << " " << std::string(name) << ": " << d->significant_blocks
                               << " significant blocks, worst relative difference "
                               << d->significant << "; others: worst normalised difference "
                               << d->negligible);
            CHECK(d->significant < 1e-7);
            CHECK(d->negligible < 1e-10);
        }
        // Every matrix is exercised somewhere (the blade: K0 only).
        CHECK(dK.significant_blocks >= 4 * 2);
        if (model_name != "models/nrel5mw_blade.mbd") {
            CHECK(dM.significant_blocks >= 4 * 2);
            CHECK(dC.significant_blocks >= 4 * 1);
            CHECK(dQ.significant_blocks >= 4 * 1);
        }
        if (model_name == "models/double_pendulum.mbd") CHECK(largest_dK_chain > 1e-3);
    }
}

TEST_CASE("linear_sensitivities: exact zero blocks where a matrix does not depend on p") {
    // Gravity, stiffness and damping do not enter M; gravity and stiffness not C0.
    // m1 twice: a parameter may be listed more than once, each block is complete.
    SensitivityModel m("models/double_pendulum.mbd", "double_pendulum", "g,k,c,m1,m1",
                       {4, 5, 6, 0, 0});
    Point pt{{2.0, 1.0, 1.0, 0.8, 9.81, 5.0, 0.1}, {0.7, -1.1}, {1.3, -0.4}, {2.0, -3.0}};
    Values v = m.evaluate({pt})[0];
    const std::size_t nn = 4;
    REQUIRE(v["dM0"].size() == 5 * nn);
    for (std::size_t i = 0; i < 3 * nn; ++i) CHECK(v["dM0"][i] == 0.0); // g, k, c
    for (std::size_t i = 0; i < 2 * nn; ++i) CHECK(v["dC0"][i] == 0.0); // g, k
    for (double x : v["dQ0"]) CHECK(x == 0.0);                          // Q0 holds no parameter
    CHECK(largest(v["dM0"], 3 * nn, nn) > 0.1);                         // m1 does enter M
    CHECK(largest(v["dC0"], 2 * nn, nn) > 0.5);                         // c enters C0
    for (const char* name : {"dM0", "dC0", "dK0"})
        for (std::size_t i = 0; i < nn; ++i) CHECK(v[name][4 * nn + i] == v[name][3 * nn + i]);
    CHECK(largest(v["dK0"], 3 * nn, nn) > 0.1);
}

TEST_CASE("without --sensitivities names the generated code is unchanged") {
    const std::string dir = scratch_dir("sens_none");
    const std::string yamsc =
        std::string(YAMSC_EXE) + " " + YAMSC_SOURCE_DIR + "/models/double_pendulum.mbd";
    REQUIRE(run(yamsc + " -o " + dir + "/plain.cpp"));
    REQUIRE(run(yamsc + " --sensitivities \"\" -o " + dir + "/empty.cpp"));
    REQUIRE(run(yamsc + " --sensitivities g -o " + dir + "/with.cpp"));
    const std::string plain = read_file(dir + "/plain.cpp");
    CHECK(plain.find("linear_sensitivities") == std::string::npos);
    CHECK(read_file(dir + "/empty.cpp") == plain);
    CHECK(read_file(dir + "/with.cpp").find("linear_sensitivities") != std::string::npos);
    // A name that is not a parameter is an error, not a silent no-op.
    CHECK_FALSE(
        run(yamsc + " --sensitivities gravity -o " + dir + "/bad.cpp 2>" + dir + "/bad.log"));
    CHECK(read_file(dir + "/bad.log").find("gravity") != std::string::npos);
}
