// The quasi-steady rotor block: ROSCO's Cp/Ct/Cq table, its C1 interpolation
// (exact at the nodes, continuous first derivatives, exact partials), the
// thrust and torque formulas, and the Jacobians of a model closed by the block
// against finite differences; the wind signals of --wind.
#include "yamsc/performance_table.hpp"
#include "yamsc/rotor_aero.hpp"
#include "yamsc/wind.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace yamsc::runtime;

namespace {

const std::string table_path = std::string(YAMSC_TEST_DATA_DIR) + "/rosco/Cp_Ct_Cq.NREL5MW.txt";
constexpr double pi = 3.14159265358979323846;

const PerformanceTable& nrel_table() {
    static const PerformanceTable t = read_performance_table(table_path);
    return t;
}

double at(const PerformanceTable& t, const std::vector<double>& v, std::size_t r, std::size_t c) {
    return v[r * t.pitch_deg.size() + c];
}

/// Two DOFs: the tower top x (mass 1e5 kg, stiffness 4e5 N/m) carrying the
/// rotor thrust, and the rotor angle (inertia 4e7 kg m^2) driven by the
/// aerodynamic torque against a generator torque input.
ModelView tower_and_rotor() {
    ModelView v;
    v.nq = 2;
    v.nu = 5; // V_wind, pitch, thrust, aero_torque, gen_torque
    v.ny = 2; // rotor_speed, hub_shaft_velocity
    v.dof_names = {"x", "psi"};
    v.input_names = {"V_wind", "pitch", "thrust", "aero_torque", "gen_torque"};
    v.output_names = {"rotor_speed", "hub_shaft_velocity"};
    const double m = 1e5, k = 4e5, c = 2e3, J = 4e7;
    v.mass_matrix = [=](double, const double*, const double*, double* M) {
        M[0] = m, M[1] = 0, M[2] = 0, M[3] = J;
    };
    v.forcing = [=](double, const double* q, const double* qd, const double* u, double* F) {
        F[0] = u[2] - k * q[0] - c * qd[0];
        F[1] = u[3] - 97 * u[4];
    };
    v.jacobians = [=](double, const double*, const double*, const double*, double* dq, double* dqd,
                      double* du) {
        for (int i = 0; i < 4; ++i) dq[i] = dqd[i] = 0;
        for (int i = 0; i < 10; ++i) du[i] = 0;
        dq[0] = -k, dqd[0] = -c, du[2] = 1, du[5 + 3] = 1, du[5 + 4] = -97;
    };
    v.rhs = [=](double, const double* x, const double* u, double* xd) {
        xd[0] = x[2], xd[1] = x[3];
        xd[2] = (u[2] - k * x[0] - c * x[2]) / m;
        xd[3] = (u[3] - 97 * u[4]) / J;
    };
    v.rhs_jacobian = [=](double, const double*, const double*, double* A) {
        for (int i = 0; i < 16; ++i) A[i] = 0;
        A[0 * 4 + 2] = 1, A[1 * 4 + 3] = 1, A[2 * 4 + 0] = -k / m, A[2 * 4 + 2] = -c / m;
    };
    v.outputs = [](double, const double*, const double* qd, const double*, double* y) {
        y[0] = qd[1];
        y[1] = qd[0];
    };
    return v;
}

RotorAero nrel_aero(const ModelView& v) {
    return bind_rotor_aero(v, nrel_table(), 63.0, 1.225, "V_wind", "pitch", "thrust", "aero_torque",
                           "rotor_speed", "hub_shaft_velocity");
}

} // namespace

TEST_CASE("ROSCO's NREL 5-MW table: 36 pitch angles, 26 tip-speed ratios, three matrices") {
    const PerformanceTable& t = nrel_table();
    CHECK(t.pitch_deg.size() == 36);
    CHECK(t.tsr.size() == 26);
    CHECK(t.pitch_deg.front() == -5.0);
    CHECK(t.pitch_deg.back() == 30.0);
    CHECK(t.tsr.front() == 2.0);
    CHECK(t.tsr.back() == 14.5);
    CHECK(t.cp.size() == 936);
    CHECK(at(t, t.cp, 0, 0) == 0.006673); // the file's first value
    // Cp at TSR 7.5, pitch 0 (row 11, column 5): the design point
    CHECK(at(t, t.cp, 11, 5) == doctest::Approx(0.465861));
    std::istringstream bad("-5 0 5\n2 3\n11.4\n0.1 0.2\n");
    CHECK_THROWS_WITH_AS(read_performance_table(bad, "bad.txt"),
                         doctest::Contains("bad.txt:4: 2 values, expected 3"), std::runtime_error);
}

TEST_CASE("the interpolant passes through every node") {
    const PerformanceTable& t = nrel_table();
    double worst = 0;
    for (std::size_t r = 0; r < t.tsr.size(); ++r)
        for (std::size_t c = 0; c < t.pitch_deg.size(); ++c)
            for (const std::vector<double>* v : {&t.cp, &t.ct, &t.cq})
                worst =
                    std::max(worst, std::fabs(interpolate(t, *v, t.tsr[r], t.pitch_deg[c]).value -
                                              at(t, *v, r, c)));
    CHECK(worst < 1e-14);
}

TEST_CASE("its partial derivatives are exact and continuous across the cells") {
    const PerformanceTable& t = nrel_table();
    // exact: central differences inside a cell agree to the differences' own error
    for (double tsr : {3.3, 7.71, 12.05})
        for (double pitch : {-2.4, 0.6, 11.53, 27.9}) {
            const Coefficient c = interpolate(t, t.ct, tsr, pitch);
            const double h = 1e-6;
            const double d_tsr = (interpolate(t, t.ct, tsr + h, pitch).value -
                                  interpolate(t, t.ct, tsr - h, pitch).value) /
                                 (2 * h);
            const double d_pitch = (interpolate(t, t.ct, tsr, pitch + h).value -
                                    interpolate(t, t.ct, tsr, pitch - h).value) /
                                   (2 * h);
            CHECK(c.d_tsr == doctest::Approx(d_tsr).epsilon(1e-7));
            CHECK(c.d_pitch == doctest::Approx(d_pitch).epsilon(1e-7));
        }
    // C1: at every interior node line, the derivative from both sides agrees
    // (value and slope jump at most by the 1e-9 step times the second derivative)
    double jump_value = 0, jump_slope = 0;
    const double e = 1e-9;
    for (std::size_t r = 1; r + 1 < t.tsr.size(); ++r) {
        const double x = t.tsr[r];
        for (double pitch : {-4.5, 1.3, 11.53, 22.2}) {
            const Coefficient lo = interpolate(t, t.cq, x - e, pitch);
            const Coefficient hi = interpolate(t, t.cq, x + e, pitch);
            jump_value = std::max(jump_value, std::fabs(hi.value - lo.value));
            jump_slope = std::max(jump_slope, std::fabs(hi.d_tsr - lo.d_tsr));
        }
    }
    for (std::size_t c = 1; c + 1 < t.pitch_deg.size(); ++c) {
        const double y = t.pitch_deg[c];
        for (double tsr : {2.2, 7.3, 9.9, 14.0}) {
            const Coefficient lo = interpolate(t, t.ct, tsr, y - e);
            const Coefficient hi = interpolate(t, t.ct, tsr, y + e);
            jump_value = std::max(jump_value, std::fabs(hi.value - lo.value));
            jump_slope = std::max(jump_slope, std::fabs(hi.d_pitch - lo.d_pitch));
        }
    }
    CHECK(jump_value < 1e-9);
    CHECK(jump_slope < 1e-7);
    // beyond the table: continued linearly with the edge slope, C1 at the edge
    const Coefficient edge = interpolate(t, t.cp, 14.5, 3.0);
    const Coefficient out = interpolate(t, t.cp, 15.0, 3.0);
    CHECK(out.value == doctest::Approx(edge.value + 0.5 * edge.d_tsr).epsilon(1e-12));
    CHECK(out.d_tsr == doctest::Approx(edge.d_tsr).epsilon(1e-12));
    CHECK(interpolate(t, t.cp, 14.5 - e, 3.0).d_tsr == doctest::Approx(edge.d_tsr).epsilon(1e-6));
}

TEST_CASE(
    "thrust and torque at a table point are 1/2 rho pi R^2 V^2 Ct and 1/2 rho pi R^3 V^2 Cq") {
    const ModelView v = tower_and_rotor();
    const RotorAero aero = nrel_aero(v);
    // TSR 7.5 (row 11) and pitch 0 (column 5) at 8 m/s: Omega = 7.5 * 8 / 63
    const double V = 8.0, omega = 7.5 * V / 63.0;
    const RotorLoads l = rotor_loads(aero, V, omega, 0.0);
    const PerformanceTable& t = nrel_table();
    const double ct = at(t, t.ct, 11, 5), cq = at(t, t.cq, 11, 5);
    CHECK(l.tsr == doctest::Approx(7.5).epsilon(1e-15));
    CHECK(l.thrust == doctest::Approx(0.5 * 1.225 * pi * 63 * 63 * V * V * ct).epsilon(1e-14));
    CHECK(l.torque == doctest::Approx(0.5 * 1.225 * pi * 63 * 63 * 63 * V * V * cq).epsilon(1e-14));
    // the numbers: Ct 0.7867... -> about 470 kN; Cq -> about 4.9 MN m
    CHECK(l.thrust == doctest::Approx(0.5 * 1.225 * pi * 3969 * 64 * ct));
    CHECK(l.power == doctest::Approx(l.torque * omega));
    CHECK_THROWS_AS(rotor_loads(aero, -1.0, omega, 0.0), std::invalid_argument);
}

TEST_CASE("a model closed by the rotor block: its Jacobians are those of its equations") {
    const ModelView base = tower_and_rotor();
    const ModelView v = with_rotor_aero(base, nrel_aero(base));
    CHECK(v.ny == 9);
    CHECK(v.output_names[2] == "aero_thrust");
    const std::vector<double> q{0.3, 1.0}, qd{-0.4, 1.1};
    const std::vector<double> u{12.0, 0.05, 1e4, -2e4, 3e4};
    std::vector<double> dq(4), dqd(4), du(10);
    v.jacobians(0, q.data(), qd.data(), u.data(), dq.data(), dqd.data(), du.data());
    auto F = [&](std::vector<double> qq, std::vector<double> qqd, std::vector<double> uu) {
        std::vector<double> f(2);
        v.forcing(0, qq.data(), qqd.data(), uu.data(), f.data());
        return f;
    };
    double worst = 0;
    for (int j = 0; j < 2; ++j) {
        const double h = 1e-5;
        auto qp = qd, qm = qd;
        qp[j] += h, qm[j] -= h;
        const auto fp = F(q, qp, u), fm = F(q, qm, u);
        for (int r = 0; r < 2; ++r) {
            const double fd = (fp[r] - fm[r]) / (2 * h);
            worst = std::max(worst, std::fabs(dqd[r * 2 + j] - fd) / (1 + std::fabs(fd)));
        }
    }
    for (int j = 0; j < 5; ++j) {
        const double h = j >= 2 ? 1.0 : 1e-6;
        auto up = u, um = u;
        up[j] += h, um[j] -= h;
        const auto fp = F(q, qd, up), fm = F(q, qd, um);
        for (int r = 0; r < 2; ++r) {
            const double fd = (fp[r] - fm[r]) / (2 * h);
            worst = std::max(worst, std::fabs(du[r * 5 + j] - fd) / (1 + std::fabs(fd)));
        }
    }
    CHECK(worst < 1e-6);
    // the tower's aerodynamic damping: dThrust/dx' = -dT/dV_rel < 0
    CHECK(dqd[0] < -2e3 - 1e4);
    // rhs_jacobian: the same loads through M^-1
    std::vector<double> x{q[0], q[1], qd[0], qd[1]}, A(16);
    v.rhs_jacobian(0, x.data(), u.data(), A.data());
    for (int j = 0; j < 4; ++j) {
        const double h = 1e-6;
        auto xp = x, xm = x;
        xp[j] += h, xm[j] -= h;
        std::vector<double> fp(4), fm(4);
        v.rhs(0, xp.data(), u.data(), fp.data());
        v.rhs(0, xm.data(), u.data(), fm.data());
        for (int r = 0; r < 4; ++r)
            CHECK(A[r * 4 + j] ==
                  doctest::Approx((fp[r] - fm[r]) / (2 * h)).epsilon(1e-6).scale(1e-6));
    }
}

TEST_CASE("--wind: steady, a step and a table of time and speed") {
    CHECK(parse_wind("11.4")(123.0) == 11.4);
    const WindSignal step = parse_wind("step:8:14:t=10");
    CHECK(step(9.999) == 8.0);
    CHECK(step(10.5) == 14.0);
    const std::string path = std::string(YAMSC_TEST_BINARY_DIR) + "/wind_test.csv";
    std::ofstream(path) << "time,wind\n0,8\n10,10\n20,9\n";
    const WindSignal w = parse_wind(path);
    CHECK(w(5.0) == doctest::Approx(9.0));
    CHECK(w(15.0) == doctest::Approx(9.5));
    CHECK(w(30.0) == 9.0);
    // An OpenFAST uniform wind file: '!' comments, the speed in the second column.
    const std::string wnd = std::string(YAMSC_TEST_BINARY_DIR) + "/wind_test.wnd";
    std::ofstream(wnd) << "! Uniform wind file\n! Time WindSpeed WindDir VertSpeed\n"
                          "   0.0  8.0  0.0  0.0\n  60.0  8.0  0.0  0.0\n"
                          "  60.00625  14.0  0.0  0.0\n";
    const WindSignal uniform = parse_wind(wnd);
    CHECK(uniform(30.0) == 8.0);
    CHECK(uniform(61.0) == 14.0);
    CHECK(uniform(60.003125) == doctest::Approx(11.0));
    CHECK_THROWS_AS(parse_wind("step:8:14"), std::invalid_argument);
    CHECK_THROWS_AS(parse_wind("no_such_file.csv"), std::runtime_error);
}
