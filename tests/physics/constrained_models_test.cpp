// The constrained models of models/ against their oracles: the benchmark
// bicycle's linearized eigenvalues, weave and capsize speeds and its nonlinear
// motion; the four-bar and the slider-crank against their closed-form
// kinematics and Lagrange equations; the rolling disk's steady turning and
// stability bound; the prescribed pitch against a stiff pitch servo; the pitch
// cylinder's loop.
#include "bicycle_benchmark.hpp"
#include "equations_fixture.hpp"
#include "planar_linkages.hpp"
#include "rolling_disk.hpp"

#include <yamsc/constraints.hpp>
#include <yamsc/simulation.hpp>

#include <Eigen/Dense>

using namespace yamsc;

namespace {

/// A model file compiled, its constrained view and the consistent start.
struct Loaded {
    test::Compiled compiled;
    runtime::ModelView view; // constrained

    int dof(const std::string& name) const {
        for (int i = 0; i < view.nq; ++i)
            if (view.dof_names[std::size_t(i)] == name) return i;
        FAIL("no DOF " << name);
        return -1;
    }
    int output(const std::string& name) const {
        for (int i = 0; i < view.ny; ++i)
            if (view.output_names[std::size_t(i)] == name) return i;
        FAIL("no output " << name);
        return -1;
    }
};

Loaded load(const std::string& model, const std::map<std::string, double>& params = {}) {
    Loaded l;
    l.compiled = test::compile_model(test::derive_file(model), params);
    REQUIRE(l.compiled.view.nc > 0);
    l.view = runtime::constrain(l.compiled.view);
    return l;
}

/// The eigenvalues of a row-major n x n matrix.
std::vector<std::complex<double>> eigenvalues(const std::vector<double>& A, int n) {
    Eigen::MatrixXd m(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) m(i, j) = A[std::size_t(i * n + j)];
    Eigen::EigenSolver<Eigen::MatrixXd> es(m, false);
    std::vector<std::complex<double>> out;
    for (int i = 0; i < n; ++i) out.push_back(es.eigenvalues()[i]);
    return out;
}

// ----------------------------------------------------------------------------------
// The bicycle

struct Bicycle {
    Loaded m = load("models/whipple_bicycle.mbd");
    int lean = m.dof("lean"), delta = m.dof("delta"), thR = m.dof("thR"), thF = m.dof("thF"),
        xP = m.dof("xP");

    /// Upright, straight ahead at speed v (made consistent).
    std::vector<double> upright(double v, double lean_rate = 0) const {
        const int nq = m.view.nq;
        std::vector<double> x(std::size_t(m.view.nx()), 0.0);
        x[std::size_t(nq + xP)] = v;
        x[std::size_t(nq + thR)] = v / 0.3;
        x[std::size_t(nq + thF)] = v / 0.35;
        x[std::size_t(nq + lean)] = lean_rate;
        return runtime::consistent_initial_state(m.view, 0, x, {0.0}).x;
    }

    /// The linear model's lean/steer block [lean, delta, lean', delta'] (4 x 4)
    /// at speed v, after checking that the other states do not feed it.
    Eigen::Matrix4d lean_steer(double v) const {
        const auto lin = runtime::reduced_linear_model(m.view, upright(v), {0.0});
        const int ns = int(lin.state_names.size());
        std::vector<int> idx;
        for (const std::string name : {"lean", "delta", "lean'", "delta'"}) {
            int k = -1;
            for (int i = 0; i < ns; ++i)
                if (lin.state_names[std::size_t(i)] == name) k = i;
            REQUIRE_MESSAGE(k >= 0, name << " is not an independent state");
            idx.push_back(k);
        }
        Eigen::Matrix4d A;
        double coupling = 0, scale = 0;
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < ns; ++j) {
                const double a = lin.A[std::size_t(idx[std::size_t(i)] * ns + j)];
                const auto col = std::find(idx.begin(), idx.end(), j);
                if (col != idx.end())
                    A(i, int(col - idx.begin())) = a;
                else
                    coupling = std::max(coupling, std::fabs(a));
                scale = std::max(scale, std::fabs(a));
            }
        }
        CHECK(coupling <= 1e-10 * scale);
        return A;
    }
};

/// The linearized benchmark from lean/steer initial values, by RK4 (h = 1e-4).
std::vector<double> linear_lean(const bicycle::Matrices& mat, double v, double lean_rate, double dt,
                                int rows) {
    const Eigen::Matrix4d A = bicycle::state_matrix(mat, 9.81, v);
    Eigen::Vector4d z(0, 0, lean_rate, 0);
    std::vector<double> out{z[0]};
    const int sub = int(std::lround(dt / 1e-4));
    const double h = dt / sub;
    for (int r = 1; r < rows; ++r) {
        for (int s = 0; s < sub; ++s) {
            const Eigen::Vector4d k1 = A * z, k2 = A * (z + 0.5 * h * k1),
                                  k3 = A * (z + 0.5 * h * k2), k4 = A * (z + h * k3);
            z += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        }
        out.push_back(z[0]);
    }
    return out;
}

} // namespace

TEST_CASE("whipple bicycle: lin gives the benchmark's eigenvalues from 0 to 10 m/s") {
    const Bicycle bike;
    const bicycle::Parameters p;
    const auto mat = bicycle::matrices(p);
    for (const auto& row : bicycle::published_table()) {
        const auto ev = bicycle::sorted_eigenvalues(bike.lean_steer(row.v));
        const auto oracle = bicycle::eigenvalues(mat, p.g, row.v);
        for (std::size_t i = 0; i < 4; ++i) {
            INFO("v = " << row.v << ": " << ev[i] << " vs oracle " << oracle[i] << ", table "
                        << row.ev[i]);
            CHECK(std::abs(ev[i] - oracle[i]) <= 1e-8 * std::abs(oracle[i]));
            // The table's 14 decimals: its smallest entry (-0.0040669007697) has 11
            // digits.
            CHECK(std::abs(ev[i] - row.ev[i]) <= std::max(1e-8 * std::abs(row.ev[i]), 2e-14));
        }
        // Every other state of the linear model is a zero eigenvalue (positions,
        // heading, wheel angles and the forward speed are neutral).
        const auto lin = runtime::reduced_linear_model(bike.m.view, bike.upright(row.v), {0.0});
        const int ns = int(lin.state_names.size());
        int zeros = 0;
        for (auto e : eigenvalues(lin.A, ns))
            if (std::abs(e) < 1e-6) ++zeros;
        CHECK(zeros == ns - 4);
    }
}

TEST_CASE("whipple bicycle: the linear model's lean/steer block is the benchmark's") {
    const Bicycle bike;
    const auto mat = bicycle::matrices(bicycle::Parameters{});
    for (double v : {0.0, 2.5, 4.6, 8.0}) {
        const Eigen::Matrix4d A = bike.lean_steer(v);
        const Eigen::Matrix2d K = -mat.M.inverse() * (9.81 * mat.K0 + v * v * mat.K2);
        const Eigen::Matrix2d C = -mat.M.inverse() * (v * mat.C1);
        INFO("v = " << v << "\n" << A);
        CHECK((A.topLeftCorner<2, 2>()).norm() < 1e-12);
        CHECK((A.topRightCorner<2, 2>() - Eigen::Matrix2d::Identity()).norm() < 1e-12);
        CHECK((A.bottomLeftCorner<2, 2>() - K).norm() <= 1e-9 * K.norm());
        CHECK((A.bottomRightCorner<2, 2>() - C).norm() <= 1e-9 * std::max(C.norm(), 1.0));
    }
}

TEST_CASE("whipple bicycle: weave and capsize speeds from yamsc's linear model") {
    const Bicycle bike;
    auto abscissa = [&](double v) {
        return bicycle::abscissa(bicycle::sorted_eigenvalues(bike.lean_steer(v)));
    };
    const double weave = bicycle::bisect(abscissa, 4, 5);
    const double capsize = bicycle::bisect(abscissa, 6, 7);
    MESSAGE("weave " << weave << " m/s, capsize " << capsize << " m/s");
    CHECK(std::fabs(weave - bicycle::weave_speed) < 1e-8);
    CHECK(std::fabs(capsize - bicycle::capsize_speed) < 1e-8);
}

TEST_CASE("whipple bicycle: nonlinear motion is self-stable at 4.6 m/s and "
          "falls at 3 m/s") {
    const Bicycle bike;
    const auto mat = bicycle::matrices(bicycle::Parameters{});
    for (double v : {4.6, 3.0}) {
        // A small kick: the nonlinear lean follows the linear benchmark's.
        runtime::SimulationOptions o;
        o.method = runtime::Method::rk4;
        o.dt = 1e-3;
        o.dt_out = 0.01;
        o.t_end = 3;
        o.u = {0.0};
        const double kick = 1e-4;
        o.x0 = bike.upright(v, kick);
        const auto r = runtime::simulate(bike.m.view, o);
        const auto lin = linear_lean(mat, v, kick, 0.01, int(r.rows()));
        double worst = 0, peak = 0;
        for (std::size_t i = 0; i < r.rows(); ++i) {
            worst = std::max(worst, std::fabs(r.state_row(i)[bike.lean] - lin[i]));
            peak = std::max(peak, std::fabs(lin[i]));
        }
        INFO("v = " << v << ": nonlinear vs linear lean, worst " << worst << " of " << peak);
        // Second-order terms: relative size of the amplitude (~1e-4); the step:
        // 1e-12.
        CHECK(worst <= 1e-3 * peak);
        // A large kick: 0.5 rad/s of lean rate.
        o.t_end = v > 4 ? 10 : 3;
        o.x0 = bike.upright(v, 0.5);
        const auto big = runtime::simulate(bike.m.view, o);
        double first = 0, last = 0,
               largest = 0; // max |lean| over [0, 2] s, [t_end - 2, t_end], all
        for (std::size_t i = 0; i < big.rows(); ++i) {
            const double lean = std::fabs(big.state_row(i)[bike.lean]);
            if (big.time[i] <= 2) first = std::max(first, lean);
            if (big.time[i] >= o.t_end - 2) last = std::max(last, lean);
            largest = std::max(largest, lean);
        }
        MESSAGE("v = " << v << ", lean rate kick 0.5 rad/s: max |lean| " << first
                       << " rad over [0, 2] s, " << last << " rad over the last 2 s of " << o.t_end
                       << " s");
        if (v > 4) {
            // Self-stable: the weave (Re -0.33 /s at 4.6 m/s) and capsize modes decay.
            CHECK(largest < 0.2);
            CHECK(last < 0.2 * first);
        } else {
            // The weave grows (Re +1.71 /s at 3 m/s): the bicycle falls over within 3 s.
            CHECK(largest > 1.0);
        }
        const int pos = bike.m.output("constraint_position_error");
        CHECK(big.output_row(big.rows() - 1)[pos] < 1e-10);
    }
}

// ----------------------------------------------------------------------------------
// Four-bar and slider-crank

namespace {

/// The linkage's state from its oracle at crank angle th and rate w: the crank,
/// the second link relative to the crank, the third coordinate as `third` says.
template <class Mechanism, class Third>
std::vector<double> linkage_state(const Mechanism& mech, double th, double w, Third third) {
    const auto s = mech.links(th);
    const auto [q3, dq3] = third(s);
    return {th, s[1].b - th, q3, w, (s[1].db - 1) * w, dq3 * w};
}

template <class Mechanism, class Third>
void check_linkage(const std::string& model, const Mechanism& mech, Third third) {
    const Loaded l = load(model);
    const linkage::OneDof<Mechanism> oracle{mech};
    const double th0 = 0.3, w0 = 8.0;
    runtime::SimulationOptions o;
    o.method = runtime::Method::rk4;
    o.dt = 1e-4;
    o.dt_out = 0.01;
    o.t_end = 2;
    o.u = std::vector<double>(std::size_t(l.view.nu), 0.0);
    o.x0 = linkage_state(mech, th0, w0, third);
    // The model's own start made consistent is the oracle's to rounding.
    const auto consistent = runtime::consistent_initial_state(l.view, 0, o.x0, o.u);
    for (std::size_t i = 0; i < o.x0.size(); ++i)
        CHECK(std::fabs(consistent.x[i] - o.x0[i]) < 1e-13);
    const auto r = runtime::simulate(l.view, o);
    double worst = 0, worst_rate = 0;
    double th = th0, w = w0;
    for (std::size_t i = 1; i < r.rows(); ++i) {
        const auto s = oracle.integrate(th, w, 1e-4, 100);
        th = s[0];
        w = s[1];
        worst = std::max(worst, std::fabs(r.state_row(i)[0] - th));
        worst_rate = std::max(worst_rate, std::fabs(r.state_row(i)[3] - w));
        // The dependent coordinates on the closed form.
        const auto x = linkage_state(mech, r.state_row(i)[0], r.state_row(i)[3], third);
        CHECK(std::fabs(r.state_row(i)[1] - x[1]) < 1e-10);
        CHECK(std::fabs(r.state_row(i)[2] - x[2]) < 1e-10);
    }
    MESSAGE(model << ": crank angle against the Lagrange oracle, worst " << worst << " rad, rate "
                  << worst_rate << " rad/s over 2 s");
    CHECK(worst < 1e-10);
    CHECK(worst_rate < 1e-9 * w0);
    // 100 s at a coarser step: the loop stays closed.
    o.dt = 1e-3;
    o.dt_out = 1;
    o.t_end = 100;
    const auto long_run = runtime::simulate(l.view, o);
    const auto last = long_run.output_row(long_run.rows() - 1);
    MESSAGE(model << ": after 100 s |Phi| = " << last[l.output("constraint_position_error")]
                  << ", |r| = " << last[l.output("constraint_velocity_error")]);
    CHECK(last[l.output("constraint_position_error")] < 1e-10);
    CHECK(last[l.output("constraint_velocity_error")] < 1e-10);
    // Energy is conserved (no loads): the oracle's energy at the end.
    const double* x = long_run.state_row(long_run.rows() - 1);
    CHECK(oracle.energy(x[0], x[3]) == doctest::Approx(oracle.energy(th0, w0)).epsilon(1e-6));
}

} // namespace

TEST_CASE("four-bar: the crank's motion is the Lagrange oracle's; the loop "
          "stays closed") {
    const linkage::FourBar fb;
    check_linkage("models/four_bar.mbd", fb, [&](const auto& s) {
        return std::pair<double, double>{s[2].b, s[2].db};
    });
}

TEST_CASE("slider-crank: the crank's motion is the Lagrange oracle's; the loop "
          "stays closed") {
    const linkage::SliderCrank sc;
    check_linkage("models/slider_crank.mbd", sc, [&](const auto& s) {
        return std::pair<double, double>{s[2].r.x(), s[2].dr.x()};
    });
}

// ----------------------------------------------------------------------------------
// Rolling disk

TEST_CASE("rolling disk: steady turning at the closed-form yaw rate") {
    const Loaded l = load("models/rolling_disk.mbd");
    const disk::Disk d;
    const int nq = l.view.nq, lean = l.dof("lean"), yaw = l.dof("yaw"), spin = l.dof("spin");
    double worst_steady = 0;
    for (double phi : {0.1, -0.3, 0.6}) {
        for (double ws : {8.0, 25.0}) {
            const double W = d.steady_yaw_rate(phi, ws);
            std::vector<double> x(std::size_t(2 * nq), 0.0);
            x[std::size_t(lean)] = phi;
            x[std::size_t(nq + yaw)] = W;
            x[std::size_t(nq + spin)] = ws - W * std::sin(phi);
            x = runtime::consistent_initial_state(l.view, 0, x, {}).x;
            CHECK(x[std::size_t(nq + yaw)] == W); // independent speeds kept
            std::vector<double> xdot(x.size());
            l.view.rhs(0, x.data(), nullptr, xdot.data());
            const double scale = d.g / d.r; // the order of lean'' of a disk falling from rest
            INFO("phi " << phi << ", ws " << ws);
            CHECK(std::fabs(xdot[std::size_t(nq + lean)]) < 1e-12 * scale);
            CHECK(std::fabs(xdot[std::size_t(nq + yaw)]) < 1e-12 * scale);
            CHECK(std::fabs(xdot[std::size_t(nq + spin)]) < 1e-12 * scale);
            for (int k : {lean, yaw, spin})
                worst_steady = std::max(worst_steady, std::fabs(xdot[std::size_t(nq + k)]));
            // Off the steady yaw rate the lean accelerates.
            auto off = x;
            off[std::size_t(nq + yaw)] *= 1.05;
            off = runtime::consistent_initial_state(l.view, 0, off, {}).x;
            l.view.rhs(0, off.data(), nullptr, xdot.data());
            CHECK(std::fabs(xdot[std::size_t(nq + lean)]) > 1e-4 * scale);
        }
    }
    MESSAGE("rolling disk: largest acceleration at the closed form's steady turning "
            << worst_steady << " rad/s^2");
    // And it stays steady in a simulation.
    const double phi = 0.3, ws = 25, W = d.steady_yaw_rate(phi, ws);
    runtime::SimulationOptions o;
    o.method = runtime::Method::rk4;
    o.dt = 1e-4;
    o.dt_out = 0.1;
    o.t_end = 2;
    std::vector<double> x(std::size_t(2 * nq), 0.0);
    x[std::size_t(lean)] = phi;
    x[std::size_t(nq + yaw)] = W;
    x[std::size_t(nq + spin)] = ws - W * std::sin(phi);
    o.x0 = runtime::consistent_initial_state(l.view, 0, x, {}).x;
    const auto r = runtime::simulate(l.view, o);
    double drift = 0;
    for (std::size_t i = 0; i < r.rows(); ++i)
        drift = std::max(drift, std::fabs(r.state_row(i)[lean] - phi));
    MESSAGE("rolling disk: lean drift over 2 s of steady turning " << drift << " rad");
    CHECK(drift < 1e-9);
    CHECK(r.state_row(r.rows() - 1)[yaw] == doctest::Approx(W * 2).epsilon(1e-9));
}

TEST_CASE("rolling disk: upright rolling is stable above v^2 = g r / 3, with "
          "the closed form's frequency") {
    const Loaded l = load("models/rolling_disk.mbd");
    const disk::Disk d;
    const int nq = l.view.nq;
    for (double ratio : {0.5, 0.95, 1.05, 2.0, 5.0}) {
        const double ws = ratio * d.critical_spin();
        std::vector<double> x(std::size_t(2 * nq), 0.0);
        x[std::size_t(nq + l.dof("spin"))] = ws;
        x = runtime::consistent_initial_state(l.view, 0, x, {}).x;
        const auto lin = runtime::reduced_linear_model(l.view, x, {});
        const int ns = int(lin.state_names.size());
        const double s2 = d.lean_eigenvalue_squared(ws);
        const std::complex<double> want = s2 > 0 ? std::complex<double>(std::sqrt(s2), 0)
                                                 : std::complex<double>(0, std::sqrt(-s2));
        double best = INFINITY, largest_re = -INFINITY;
        for (auto e : eigenvalues(lin.A, ns)) {
            best = std::min(best, std::abs(e - want));
            largest_re = std::max(largest_re, e.real());
        }
        INFO("ws / ws_crit = " << ratio << ": closed form " << want);
        CHECK(best <= 1e-8 * std::abs(want));
        if (ratio < 1)
            CHECK(largest_re == doctest::Approx(std::sqrt(s2)).epsilon(1e-8));
        else
            CHECK(largest_re < 1e-8 * std::abs(want)); // neutrally stable: no growth
    }
}

// ----------------------------------------------------------------------------------
// Prescribed pitch against a stiff pitch servo

namespace {

/// theta_cmd = A sin(w t) with its rates; Q = 0.
runtime::InputFunction pitch_command() {
    return [](double t, double* u) {
        const double A = 0.1, w = 2.0;
        u[0] = 0;
        u[1] = A * std::sin(w * t);
        u[2] = A * w * std::cos(w * t);
        u[3] = -A * w * w * std::sin(w * t);
    };
}

runtime::SimulationResult run_rotor(const runtime::ModelView& view, int nq) {
    runtime::SimulationOptions o;
    o.method = runtime::Method::cvode;
    o.rtol = 1e-11;
    o.atol = 1e-12;
    o.dt = 0.01;
    o.t_end = 2;
    o.u_of_t = pitch_command();
    o.x0.assign(std::size_t(2 * nq), 0.0);
    o.x0[std::size_t(nq + 0)] = 1.2; // psi'
    o.x0[std::size_t(nq + 1)] = 0.2; // p1' = theta_cmd'(0)
    o.x0[std::size_t(nq + 2)] = 0.2; // p2'
    return runtime::simulate(view, o);
}

} // namespace

TEST_CASE("prescribed pitch: the stiff servo's motion and torque tend to the "
          "prescribed ones") {
    const Loaded pres = load("models/rotor_prescribed_pitch.mbd");
    const int nq = pres.view.nq;
    const auto ref = run_rotor(pres.view, nq);
    const int holding = pres.output("lambda:pitch1");
    double last_err = INFINITY, last_torque_err = INFINITY;
    for (double K : {1e7, 1e8, 1e9}) {
        // Damping ratio about 0.7 of the pitch mode (inertia J_pitch = 2000 kg
        // m^2).
        const double D = 2 * 0.7 * std::sqrt(K * 2.0e3);
        const auto spring_c = test::compile_model(
            test::derive_file("models/rotor_pitch_spring.mbd"), {{"K_p", K}, {"D_p", D}});
        const auto r = run_rotor(spring_c.view, nq);
        REQUIRE(r.rows() == ref.rows());
        int torque = -1;
        for (int i = 0; i < spring_c.view.ny; ++i)
            if (spring_c.view.output_names[std::size_t(i)] == "pitch_torque1") torque = i;
        double err = 0, torque_err = 0, torque_peak = 0;
        for (std::size_t i = 0; i < r.rows(); ++i) {
            for (int k = 0; k < nq; ++k) // psi, p1, p2, b1, b2
                err = std::max(err, std::fabs(r.state_row(i)[k] - ref.state_row(i)[k]));
            if (r.time[i] > 0.5) { // after the servo's start-up transient
                torque_err = std::max(
                    torque_err, std::fabs(r.output_row(i)[torque] - ref.output_row(i)[holding]));
                torque_peak = std::max(torque_peak, std::fabs(ref.output_row(i)[holding]));
            }
        }
        MESSAGE("K_p = " << K << ": largest state difference " << err << ", pitch torque "
                         << torque_err << " of " << torque_peak << " N m");
        // Converges like 1 / K: each tenfold stiffer servo is closer by well over
        // 3x.
        CHECK(err < last_err / 3);
        CHECK(torque_err < last_torque_err / 3);
        last_err = err;
        last_torque_err = torque_err;
        if (K == 1e9) {
            CHECK(err < 1e-4);
            CHECK(torque_err < 1e-2 * torque_peak);
        }
    }
}

// ----------------------------------------------------------------------------------
// The pitch cylinder

TEST_CASE("pitch cylinder: the stroke is the closed form of the pitch; the "
          "loop stays closed") {
    const Loaded l = load("models/pitch_cylinder.mbd");
    const int pitch = l.dof("pitch"), stroke = l.dof("stroke"), beta = l.dof("beta");
    runtime::SimulationOptions o;
    o.method = runtime::Method::rk4;
    o.dt = 1e-3;
    o.dt_out = 0.5;
    o.t_end = 100;
    o.u = {2.0e5, 0.0}; // the cylinder pushes against the blade's centrifugal
                        // pitching moment
    std::vector<double> x(std::size_t(l.view.nx()), 0.0);
    x[std::size_t(beta)] = M_PI / 2;
    x[std::size_t(stroke)] = 1.5;
    x[std::size_t(l.view.nq + l.dof("psi"))] = 1.2;
    o.x0 = x;
    const auto r = runtime::simulate(l.view, o);
    const double r_arm = 0.6, xc = 0.6, yc = -1.5;
    double worst = 0, moved = 0;
    for (std::size_t i = 0; i < r.rows(); ++i) {
        const double p = r.state_row(i)[pitch];
        const double want = std::hypot(r_arm * std::cos(p) - xc, r_arm * std::sin(p) - yc);
        worst = std::max(worst, std::fabs(r.state_row(i)[stroke] - want));
        moved = std::max(moved, std::fabs(p));
    }
    CHECK(moved > 0.1);
    CHECK(worst < 1e-10);
    const auto last = r.output_row(r.rows() - 1);
    CHECK(last[l.output("constraint_position_error")] < 1e-10);
    CHECK(last[l.output("constraint_velocity_error")] < 1e-10);
}
