// `yamsc lin --format openfast-lin`: the .lin files read back by an independent
// reader (read_openfast_lin.py, numpy only, parsing them as OpenFAST's tools
// do) give A's eigenfrequencies equal to those `yamsc lin` prints, to 1e-9;
// their headers hold the point; a from-openfast rotor's blade DOFs carry
// ElastoDyn's descriptions and the rotating-frame flag; and the files written
// at N azimuths, MBC3-transformed and averaged by the reader, give the
// frequencies of `yamsc lin --mbc3`.
#include "test_files.hpp"

#include "analysis/openfast_lin_model.hpp"
#include "driver/commands.hpp"
#include "openfast/from_openfast.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace test_support;

namespace {

const std::string source_dir = YAMSC_SOURCE_DIR;

struct Run {
    int status;
    std::string out, err;
};

Run run(const std::string& dir, const std::string& command) {
    const int status = exit_status("cd '" + dir + "' && " + command + " >run.out 2>run.err");
    return {status, read_file(dir + "/run.out"), read_file(dir + "/run.err")};
}

Run run_yamsc(const std::string& dir, const std::string& args) {
    return run(dir, std::string(YAMSC_EXE) + " " + args);
}

/// What the reader printed: header values, state rows, frequencies, matrix sizes.
struct Reading {
    std::map<std::string, double> header;
    std::vector<std::string> x; // "<T|F> <order> <description>"
    std::vector<double> freq, mbc3;
    std::map<std::string, std::pair<int, int>> matrices;
};

Reading read_back(const std::string& dir, const std::string& args) {
    const Run r = run(dir, std::string(YAMSC_PYTHON) + " " + source_dir +
                               "/tests/cli/read_openfast_lin.py " + args);
    REQUIRE_MESSAGE(r.status == 0, r.err);
    Reading out;
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream s(line);
        std::string kind;
        s >> kind;
        if (kind == "header") {
            std::string key;
            double v = 0;
            s >> key >> v;
            out.header[key] = v;
        } else if (kind == "x") {
            int row = 0;
            s >> row;
            std::string rest;
            std::getline(s, rest);
            out.x.push_back(rest.substr(1));
        } else if (kind == "freq" || kind == "mbc3") {
            double v = 0;
            s >> v;
            (kind == "freq" ? out.freq : out.mbc3).push_back(v);
        } else if (kind == "matrix") {
            std::string name;
            int rows = 0, cols = 0;
            s >> name >> rows >> cols;
            out.matrices[name] = {rows, cols};
        }
    }
    return out;
}

/// The frequencies [Hz] of the modes in `lin --json` (plain or --mbc3) that are not rigid.
std::vector<double> json_frequencies(const std::string& json) {
    std::vector<double> out;
    for (auto at = json.find("\"freq_hz\":"); at != std::string::npos;
         at = json.find("\"freq_hz\":", at + 1)) {
        const auto rigid = json.find("\"rigid_body\":", at);
        if (json.compare(rigid + 13, 4, "true") == 0) continue;
        out.push_back(std::stod(json.substr(at + 10)));
    }
    return out;
}

/// Each of yamsc's frequencies is one of the reader's, to `tol` relative; the worst.
double worst_match(const std::vector<double>& ours, const std::vector<double>& read, double tol) {
    REQUIRE(!ours.empty());
    double worst = 0;
    for (double f : ours) {
        double best = 1e300;
        for (double g : read) best = std::min(best, std::fabs(g / f - 1));
        CAPTURE(f);
        CHECK(best < tol);
        worst = std::max(worst, best);
    }
    return worst;
}

/// A from-openfast rotor: tower fore-aft, generator azimuth, the blades' first flap modes.
std::string rotor_model(const std::string& dir) {
    yamsc::driver::FromOpenFastOptions o;
    o.deck = std::string(YAMSC_TEST_DATA_DIR) +
             "/reference/land_16dof_free_decay/NREL5MW_Onshore_FreeDecay.fst";
    o.output = dir + "/rotor.mbd";
    for (const char* off :
         {"TwSSDOF1", "TwFADOF2", "TwSSDOF2", "YawDOF", "DrTrDOF", "EdgeDOF", "FlapDOF2"})
        o.dofs.emplace_back(off, false);
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    return o.output;
}

} // namespace

TEST_CASE("lin --format openfast-lin: the 3-DOF turbine's file reads back to lin's modes") {
    const std::string dir = scratch_dir("openfast_lin", "land_3dof");
    const std::string model = source_dir + "/models/nrel5mw_land_3dof.mbd";
    const Run r = run_yamsc(
        dir, "lin " + model + " --set Omega=1.2671 --format openfast-lin -o case.lin --json");
    REQUIRE_MESSAGE(r.status == 0, r.err);
    const Reading f = read_back(dir, "single case.lin");
    CHECK(f.header.at("nx") == 6);
    CHECK(f.header.at("nu") == 4);
    CHECK(f.header.at("ny") == 3);
    CHECK(f.header.at("azimuth") == 0);
    // The model's `linearize { psi' = Omega }`: the rotor DOF is the one with a rate.
    CHECK(f.header.at("rotor_speed") == 1.2671);
    CHECK(f.matrices.at("A") == std::make_pair(6, 6));
    CHECK(f.matrices.at("B") == std::make_pair(6, 4));
    CHECK(f.matrices.at("C") == std::make_pair(3, 6));
    CHECK(f.matrices.at("D") == std::make_pair(3, 4));
    REQUIRE(f.x.size() == 6);
    CHECK(f.x[0] == "F 2 yamsc q1 DOF, m");
    CHECK(f.x[3] == "F 2 yamsc First time derivative of q1 DOF, m/s");
    const double worst = worst_match(json_frequencies(r.out), f.freq, 1e-9);
    MESSAGE("3-DOF: worst relative frequency difference " << worst);
    CHECK(temporaries(dir).empty());
}

TEST_CASE("lin --format openfast-lin: a rotor's blade DOFs as ElastoDyn's, and MBC3 from the "
          "files") {
    const std::string dir = scratch_dir("openfast_lin", "rotor");
    const std::string model = rotor_model(dir);

    // One point: every DOF, the azimuth free (a rigid-body mode).
    Run r = run_yamsc(dir, "lin rotor.mbd --format openfast-lin -o point.lin --json");
    REQUIRE_MESSAGE(r.status == 0, r.err);
    const Reading one = read_back(dir, "single point.lin");
    CHECK(one.header.at("nx") == 10);
    CHECK(one.header.at("rotor_speed") == doctest::Approx(12.1 * M_PI / 30).epsilon(1e-12));
    REQUIRE(one.x.size() == 10);
    CHECK(one.x[0] ==
          "F 2 ED 1st tower fore-aft bending mode DOF (internal DOF index = DOF_TFA1), m");
    CHECK(one.x[1] == "F 2 ED Variable speed generator DOF (internal DOF index = DOF_GeAz), rad");
    CHECK(one.x[3] == "T 2 ED 1st flapwise bending-mode DOF of blade 2 (internal DOF index = "
                      "DOF_BF(2,1)), m");
    CHECK(one.x[9] == "T 2 ED First time derivative of 1st flapwise bending-mode DOF of blade 3 "
                      "(internal DOF index = DOF_BF(3,1)), m/s");
    const double worst = worst_match(json_frequencies(r.out), one.freq, 1e-9);
    MESSAGE("rotor, one point: worst relative frequency difference " << worst);

    // Eight azimuths, the azimuth held: the files and lin --mbc3's modes in one run.
    r = run_yamsc(dir, "lin rotor.mbd --mbc3 --azimuths 8 --format openfast-lin -o az.lin --json");
    REQUIRE_MESSAGE(r.status == 0, r.err);
    std::string files;
    for (int k = 1; k <= 8; ++k) files += " az." + std::to_string(k) + ".lin";
    const Reading third = read_back(dir, "single az.3.lin");
    CHECK(third.header.at("nx") == 8); // psi held
    CHECK(third.header.at("azimuth") == doctest::Approx(2 * M_PI * 2 / 8).epsilon(1e-15));
    CHECK(third.x[1] == "T 2 ED 1st flapwise bending-mode DOF of blade 1 (internal DOF index = "
                        "DOF_BF(1,1)), m");
    const Reading avg = read_back(dir, "mbc3" + files);
    const double worst_mbc3 = worst_match(json_frequencies(r.out), avg.mbc3, 1e-9);
    MESSAGE("rotor, MBC3 of 8 files: worst relative frequency difference " << worst_mbc3);
    CHECK(temporaries(dir).empty());

    // --azimuths alone writes the same files (no MBC3 table); -o never names an input.
    r = run_yamsc(dir, "lin rotor.mbd --azimuths 2 --format openfast-lin -o two.lin");
    REQUIRE_MESSAGE(r.status == 0, r.err);
    CHECK(r.out.find("wrote 2 files two.1.lin .. two.2.lin") != std::string::npos);
    const std::string before = read_file(model);
    r = run_yamsc(dir, "lin rotor.mbd --format openfast-lin -o rotor.mbd");
    CHECK(r.status == 2);
    CHECK(read_file(model) == before);
    r = run_yamsc(dir, "lin rotor.mbd --format openfast-lin");
    CHECK(r.status == 2);
    CHECK(r.err.find("--format openfast-lin needs -o FILE.lin") != std::string::npos);
}

TEST_CASE("lin file: ElastoDyn's order (blades by mode) and signs (side-side negated)") {
    // A linear model M = I, F = -K q - c q' + b u, in yamsc's order (blade by blade).
    const std::vector<std::string> names{"q_ss1",      "q_b1_flap1", "q_b1_edge1", "q_b2_flap1",
                                         "q_b2_edge1", "q_b3_flap1", "q_b3_edge1"};
    const int n = 7;
    std::vector<double> K(n * n, 0.0);
    for (int i = 0; i < n; ++i) {
        K[i * n + i] = 10.0 + i;
        for (int j = 0; j < n; ++j)
            if (i != j) K[i * n + j] = 0.1 * (i + 1) + 0.01 * (j + 1);
    }
    yamsc::runtime::ModelView v;
    v.nq = n;
    v.nu = 1;
    v.ny = 2;
    v.dof_names = names;
    v.input_names = {"thrust"};
    v.output_names = {"Q_TSS1", "Q_B1E1"};
    v.mass_matrix = [n](double, const double*, const double*, double* M) {
        for (int i = 0; i < n * n; ++i) M[i] = i % (n + 1) == 0 ? 1.0 : 0.0;
    };
    v.forcing = [&K, n](double, const double* q, const double* qd, const double* u, double* F) {
        for (int i = 0; i < n; ++i) {
            F[i] = -0.2 * qd[i] + (i == 0 ? u[0] : 0.0);
            for (int j = 0; j < n; ++j) F[i] -= K[i * n + j] * q[j];
        }
    };
    v.jacobians = [&K, n](double, const double*, const double*, const double*, double* dq,
                          double* dqd, double* du) {
        for (int i = 0; i < n; ++i) {
            du[i] = i == 0 ? 1.0 : 0.0;
            for (int j = 0; j < n; ++j) {
                dq[i * n + j] = -K[i * n + j];
                dqd[i * n + j] = i == j ? -0.2 : 0.0;
            }
        }
    };
    v.rhs = [&v, n](double t, const double* x, const double* u, double* xdot) {
        std::vector<double> F(n);
        v.forcing(t, x, x + n, u, F.data());
        for (int i = 0; i < n; ++i) xdot[i] = x[n + i], xdot[n + i] = F[i];
    };
    v.outputs = [](double, const double* q, const double*, const double*, double* y) {
        y[0] = -q[0];
        y[1] = q[2];
    };
    yamsc::model::Model m;
    m.name = "fake";
    yamsc::analysis::LinFilePoint p;
    p.q.assign(n, 0.0);
    p.q[0] = 0.1;
    p.qd.assign(n, 0.0);
    p.u = {0.0};
    const yamsc::analysis::LinFile f = yamsc::analysis::lin_file(m, v, p);
    // ElastoDyn's order: BF(1..3,1) then BE(1..3,1); the file's state a is yamsc's perm[a].
    const int perm[n] = {0, 1, 3, 5, 2, 4, 6};
    const double sign[n] = {-1, 1, 1, 1, 1, 1, 1};
    REQUIRE(f.x.size() == 2 * n);
    CHECK(f.x[0].description ==
          "ED 1st tower side-to-side bending mode DOF (internal DOF index = DOF_TSS1), m");
    CHECK(f.x[0].op == -0.1);
    CHECK(!f.x[0].rotating);
    CHECK(f.x[2].description == "ED 1st flapwise bending-mode DOF of blade 2 (internal DOF "
                                "index = DOF_BF(2,1)), m");
    CHECK(f.x[4].description == "ED 1st edgewise bending-mode DOF of blade 1 (internal DOF "
                                "index = DOF_BE(1,1)), m");
    CHECK(f.x[4].rotating);
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            CAPTURE(a);
            CAPTURE(b);
            // (A by central differences of rhs: the view has no rhs_jacobian)
            CHECK(f.A.data[(n + a) * 2 * n + b] ==
                  doctest::Approx(-sign[a] * sign[b] * K[perm[a] * n + perm[b]]).epsilon(1e-8));
            CHECK(f.A.data[a * 2 * n + n + b] == doctest::Approx(a == b ? 1.0 : 0.0).epsilon(1e-8));
        }
    CHECK(f.B.data[n * 1 + 0] == -1.0); // the input drives q_ss1: ED's DOF the other way
    // Q_TSS1 = -q_ss1 is ElastoDyn's DOF itself; Q_B1E1 its BE(1,1).
    CHECK(f.C.data[0 * 2 * n + 0] == doctest::Approx(1.0).epsilon(1e-9));
    CHECK(f.C.data[1 * 2 * n + 4] == doctest::Approx(1.0).epsilon(1e-9));
    CHECK(f.y[1].rotating == false); // no Q_B2E1, Q_B3E1 siblings: not a triplet
}
