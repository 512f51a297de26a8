// The potential-flow block against closed forms: hydrostatic restoring by central
// differences against C, the radiation kernel of a Gaussian damping, the
// convolution's force in a harmonic motion against B(w) v, the added mass moved to
// the body origin, the excitation of one wave, the additional matrices.
#include "block_fixture.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace potential_test;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double rho = 1025, g = 9.80665;

/// Ground force and moment about the displaced point from the body loads (origin, body axes).
Eigen::Matrix<double, 6, 1> ground_at_point(const std::array<double, 6>& l,
                                            const Eigen::Matrix3d& R,
                                            const Eigen::Vector3d& arm_body) {
    const Eigen::Vector3d f(l[0], l[1], l[2]), m(l[3], l[4], l[5]);
    Eigen::Matrix<double, 6, 1> out;
    out.head<3>() = R * f;
    out.tail<3>() = R * (m - arm_body.cross(f));
    return out;
}

} // namespace

TEST_CASE("hydrostatics: buoyancy at rest and -C by central differences on heave, roll, pitch") {
    PotentialFlowSetup s = bare_setup();
    const double R = 5, T = 50, S = pi * R * R, V = S * T;
    const double c33 = rho * g * S, c44 = rho * g * (V * -T / 2 + pi * std::pow(R, 4) / 4);
    s.hydrostatic[14] = c33;
    s.hydrostatic[21] = s.hydrostatic[28] = c44;
    s.hydrostatic[22] = s.hydrostatic[27] = 1.5e6; // a roll-pitch coupling, to see the block
    s.displaced_volume = V;
    s.cob_x = 0.3;
    s.cob_y = -0.2;
    s.reference = {1.0, 2.0, 0.0};
    s.origin_at_rest = {1.0, 2.0, 10.0}; // the point 10 m below the body origin
    const Eigen::Vector3d arm(0, 0, -10);
    const auto block = potential_flow_block(s);

    const auto load_at = [&](const Eigen::Matrix<double, 6, 1>& q) {
        const Eigen::Matrix3d Rot = rotation(q[3], q[4], q[5]);
        const Eigen::Vector3d origin =
            Eigen::Vector3d(1, 2, 0) + q.head<3>() - Rot * arm; // the point displaced by q
        return ground_at_point(evaluate(*block, 0, frame(origin, Rot)).loads, Rot, arm);
    };
    const Eigen::Matrix<double, 6, 1> rest = load_at(Eigen::Matrix<double, 6, 1>::Zero());
    const double w = rho * g * V;
    CHECK(rest[2] == doctest::Approx(w).epsilon(1e-12));
    CHECK(rest[3] == doctest::Approx(w * (-0.2 - 2.0)).epsilon(1e-12));
    CHECK(rest[4] == doctest::Approx(-w * (0.3 - 1.0)).epsilon(1e-12));
    CHECK(rest[0] == doctest::Approx(0).epsilon(1e-9));

    Eigen::Matrix<double, 6, 6> K;
    for (int j = 0; j < 6; ++j) {
        const double h = 1e-5;
        Eigen::Matrix<double, 6, 1> q = Eigen::Matrix<double, 6, 1>::Zero();
        q[j] = h;
        const auto up = load_at(q);
        q[j] = -h;
        K.col(j) = (up - load_at(q)) / (2 * h);
    }
    Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
    for (int i = 2; i < 5; ++i)
        for (int j = 2; j < 5; ++j) C(i, j) = s.hydrostatic[static_cast<std::size_t>(6 * i + j)];
    // Yaw turns the constant part (its moments) about z: d/dyaw of Rz (0, 0, W, Mx, My, 0).
    C(3, 5) = rest[4];
    C(4, 5) = -rest[3];
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            CHECK(-K(i, j) == doctest::Approx(C(i, j)).epsilon(1e-6).scale(1e3));
}

TEST_CASE("radiation kernel of a Gaussian damping: K(t) = B0 s sqrt(2/pi) exp(-s^2 t^2 / 2)") {
    const double b0 = 2e5, s = 1.0;
    std::vector<double> omega;
    std::vector<Mat6> damping;
    for (int k = 0; k <= 800; ++k) { // 0 .. 8 rad/s, then the infinite frequency's zero
        const double w = 0.01 * k;
        omega.push_back(w);
        Mat6 b{};
        b[0] = b0 * std::exp(-w * w / (2 * s * s));
        b[7] = 0.5 * b[0];
        damping.push_back(b);
    }
    omega.push_back(8.0 * (1 + 1e-7));
    damping.push_back(Mat6{});
    const double dt = 0.1;
    const auto K = radiation_kernel(omega, damping, dt, 20);
    // 20 / 0.1 = 200 -> 201, (201 - 1) / 2 = 100 = 2^2 5^2: N = 201.
    REQUIRE(K.size() == 201);
    for (std::size_t j = 0; j < K.size(); j += 7) {
        const double t = static_cast<double>(j) * dt;
        const double exact = b0 * s * std::sqrt(2 / pi) * std::exp(-s * s * t * t / 2);
        CHECK(std::abs(K[j][0] - exact) < 1e-5 * b0);
        CHECK(std::abs(K[j][7] - 0.5 * exact) < 1e-5 * b0);
        CHECK(K[j][1] == 0);
    }
    CHECK_THROWS_AS(radiation_kernel(omega, damping, 0.5, 20), std::invalid_argument); // 8 > pi/0.5
}

TEST_CASE("radiation memory: in steady harmonic surge, the force in phase with v is -B(w) v") {
    const double b0 = 2e5, s = 1.0, dt = 0.02;
    std::vector<double> omega;
    std::vector<Mat6> damping;
    for (int k = 0; k <= 1000; ++k) {
        const double w = 0.01 * k;
        omega.push_back(w);
        Mat6 b{};
        b[0] = b0 * std::exp(-w * w / (2 * s * s));
        damping.push_back(b);
    }
    PotentialFlowSetup setup = bare_setup();
    setup.kernel_dt = dt;
    setup.radiation_kernel = radiation_kernel(omega, damping, dt, 30);
    const auto block = potential_flow_block(setup);
    REQUIRE(block->has_discrete_states());
    const double w = 0.8, amplitude = 0.5;
    const auto at = [&](double t) {
        return frame(Eigen::Vector3d(-amplitude * std::cos(w * t) / w, 0, 0),
                     Eigen::Matrix3d::Identity(),
                     Eigen::Vector3d(amplitude * std::sin(w * t), 0, 0));
    };
    // Steps of RdtnDT, as OpenFAST's: the force within a step uses the velocities
    // up to its start, so it lags the velocity by half a step on average; sample
    // it at the step's start, where the lag-0 sample is the current velocity.
    double in_phase = 0, quadrature = 0;
    const int steps = static_cast<int>(std::round(40 / dt)),
              period_steps = 3 * static_cast<int>(std::round(2 * pi / w / dt));
    const double T = period_steps * dt;
    int n = 0;
    for (int k = 0; k < steps + period_steps; ++k) {
        const double t = k * dt, t1 = (k + 1) * dt;
        const auto r0 = at(t), r1 = at(t1);
        block->update_discrete_states(t, nullptr, r0.data(), t1, nullptr, r1.data());
        if (k + 1 > steps && n < period_steps) {
            const double f = evaluate(*block, t1, r1).out[12]; // RdtFxi
            in_phase += f * std::sin(w * t1) * dt;
            quadrature += f * std::cos(w * t1) * dt;
            ++n;
        }
    }
    const double b_exact = b0 * std::exp(-w * w / (2 * s * s));
    // F = -B v - (A - A_inf) v': the sin part over whole periods is -B amplitude T / 2.
    CHECK(in_phase / (amplitude * T / 2) == doctest::Approx(-b_exact).epsilon(2e-3));
    // The cos part is -(A(w) - A_inf) w amplitude T / 2, A(w) - A_inf = -(1/w) int K(t)
    // sin(w t) dt (Ogilvie), here by Simpson's rule on the Gaussian kernel.
    double integral = 0;
    const int m = 4000;
    for (int k = 0; k <= m; ++k) {
        const double tau = 10.0 * k / m;
        const double kernel = b0 * s * std::sqrt(2 / pi) * std::exp(-s * s * tau * tau / 2);
        integral += (k == 0 || k == m ? 1 : (k % 2 ? 4 : 2)) * kernel * std::sin(w * tau);
    }
    integral *= 10.0 / m / 3;
    const double a_minus_inf = -integral / w;
    CHECK(quadrature / (amplitude * w * T / 2) == doctest::Approx(-a_minus_inf).epsilon(5e-3));
}

TEST_CASE("added mass about the body origin in body axes: J^T A_inf J") {
    PotentialFlowSetup s = bare_setup();
    Mat6 a{};
    for (int i = 0; i < 6; ++i) a[static_cast<std::size_t>(7 * i)] = 1e6 * (i + 1);
    a[4] = a[24] = -2e6; // surge-pitch
    s.added_mass_infinite = a;
    s.reference = {0, 0, 0};
    s.origin_at_rest = {0, 0, 20};
    const auto block = potential_flow_block(s);
    REQUIRE(block->has_added_mass());
    const Eigen::Matrix3d Rot = rotation(0.1, -0.05, 0.3);
    const auto r = frame(Eigen::Vector3d(1, 2, 20), Rot, Eigen::Vector3d::Zero(),
                         Eigen::Vector3d(0.2, -0.1, 0.05));
    std::array<double, 36> A{};
    block->added_mass(0, nullptr, r.data(), A.data());
    // A surge acceleration of the origin (body x) with no rotation: the point's
    // acceleration is R e_x; the force at the point -A_inf (R e_x, 0) moved to the
    // origin: f = R^T F, m = R^T M + arm x f with arm (0, 0, -20).
    Eigen::Matrix<double, 6, 1> acc = Eigen::Matrix<double, 6, 1>::Zero();
    acc.head<3>() = Rot.col(0);
    const Eigen::Matrix<double, 6, 6> Ag =
        Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(a.data());
    const Eigen::Matrix<double, 6, 1> F = Ag * acc;
    const Eigen::Vector3d f = Rot.transpose() * F.head<3>();
    const Eigen::Vector3d m = Rot.transpose() * F.tail<3>() + Eigen::Vector3d(0, 0, -20).cross(f);
    for (int i = 0; i < 3; ++i) {
        CHECK(A[static_cast<std::size_t>(6 * i)] == doctest::Approx(f[i]).scale(1));
        CHECK(A[static_cast<std::size_t>(6 * (3 + i))] == doctest::Approx(m[i]).scale(1));
    }
    // Symmetric, and the rate term: -A_inf (w x (w x arm)) at rest acceleration.
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            CHECK(A[static_cast<std::size_t>(6 * i + j)] ==
                  doctest::Approx(A[static_cast<std::size_t>(6 * j + i)]).scale(1));
}

TEST_CASE("excitation of one regular wave: Re{X a exp(i w t)}, tabulated or summed") {
    PotentialFlowSetup s = bare_setup();
    s.excitation.omega = {0.0, 0.5, 1.0, 1.0 * (1 + 1e-7)};
    s.excitation.heading = {-pi, 0.0, pi};
    for (std::size_t f = 0; f < 4; ++f)
        for (std::size_t h = 0; h < 3; ++h)
            for (int i = 0; i < 6; ++i) {
                const double wf = f == 0 ? 0.5 : s.excitation.omega[f];
                s.excitation.force.push_back(
                    f == 3 ? 0.0 : std::complex<double>(1e5 * wf * (i + 1), -2e4 * (h + 1)));
            }
    const double w = 0.75; // between 0.5 and 1: X linear in w
    const std::vector<WaveComponent> one = {{w, w * w / g, std::polar(1.5, 0.3)}};
    s.waves = std::make_shared<ComponentField>(one, pi / 2, 0.0, 0.0);
    const auto direct = potential_flow_block(s);
    s.waves = std::make_shared<ComponentField>(one, pi / 2, 0.05, 2 * pi / w * 40);
    const auto tabulated = potential_flow_block(s);
    for (double t : {0.0, 1.3, 7.77, 30.0}) {
        const auto a =
            evaluate(*direct, t, frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()));
        const auto b =
            evaluate(*tabulated, t, frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()));
        for (int i = 0; i < 6; ++i) {
            // heading pi/2 halfway between 0 and pi: Im = -2e4 (2 + 3) / 2.
            const std::complex<double> X(1e5 * w * (i + 1), -5e4);
            const double exact = (X * std::polar(1.5, 0.3 + w * t)).real();
            CHECK(a.out[static_cast<std::size_t>(i)] == doctest::Approx(exact).epsilon(1e-12));
            CHECK(a.loads[static_cast<std::size_t>(i)] == doctest::Approx(exact).epsilon(1e-12));
            // Linear between samples 0.05 s apart: error <= (w dt)^2 / 8 of the amplitude.
            CHECK(std::abs(b.out[static_cast<std::size_t>(i)] - exact) <=
                  std::abs(X) * 1.5 * w * w * 0.05 * 0.05 / 8 * 1.01);
        }
    }
    s.waves = std::make_shared<ComponentField>(one, 4.0, 0.0, 0.0); // in range modulo 2 pi
    CHECK_NOTHROW(potential_flow_block(s));
    s.excitation.heading = {0.0, 0.5};
    CHECK_THROWS_AS(potential_flow_block(s), std::invalid_argument);
}

TEST_CASE("additional matrices: F0 - C q - R B R^T q' - R Bq |R^T q'| R^T q' at the point") {
    PlatformMatrices m;
    m.f0 = {1, 2, 3, 4, 5, 6};
    for (int i = 0; i < 6; ++i) {
        m.c_lin[static_cast<std::size_t>(7 * i)] = 10.0 * (i + 1);
        m.b_lin[static_cast<std::size_t>(7 * i)] = 100.0 * (i + 1);
        m.b_quad[static_cast<std::size_t>(7 * i)] = 1000.0 * (i + 1);
    }
    const double yaw = 0.4, roll = 0.02, pitch = -0.03;
    const Eigen::Matrix3d Rot = rotation(roll, pitch, yaw);
    const Eigen::Vector3d arm(0, 0, -10), point_rest(0, 0, -10);
    const Eigen::Vector3d disp(0.5, -0.2, 0.1);
    const Eigen::Vector3d origin = point_rest + disp - Rot * arm;
    const Eigen::Vector3d v(0.3, 0.1, 0), w(0, 0, 0.02);
    const auto block = platform_matrices_block(m, {0, 0, -10}, {0, 0, 0},
                                               [] {
                                                   std::vector<int> f;
                                                   for (int i = 0; i < 18; ++i) f.push_back(i);
                                                   return f;
                                               }(),
                                               {0, 1, 2, 3, 4, 5});
    std::array<double, 6> loads{};
    std::vector<double> out(6);
    const auto r = frame(origin, Rot, v - w.cross(Rot * arm), w);
    block->evaluate(0, nullptr, r.data(), loads.data(), nullptr, out.data());
    const Eigen::Vector3d vb = Rot.transpose() * v, wb = Rot.transpose() * w;
    const Eigen::Matrix<double, 6, 1> q =
        (Eigen::Matrix<double, 6, 1>() << disp, roll, pitch, yaw).finished();
    Eigen::Matrix<double, 6, 1> body_damp;
    for (int i = 0; i < 3; ++i) {
        body_damp[i] = 100.0 * (i + 1) * vb[i] + 1000.0 * (i + 1) * std::abs(vb[i]) * vb[i];
        body_damp[3 + i] = 100.0 * (i + 4) * wb[i] + 1000.0 * (i + 4) * std::abs(wb[i]) * wb[i];
    }
    for (int i = 0; i < 6; ++i) {
        const Eigen::Vector3d d = (i < 3 ? Rot * body_damp.head<3>() : Rot * body_damp.tail<3>());
        const double exact = m.f0[static_cast<std::size_t>(i)] - 10.0 * (i + 1) * q[i] - d[i % 3];
        CHECK(out[static_cast<std::size_t>(i)] == doctest::Approx(exact).epsilon(1e-9));
    }
    const auto g = ground_at_point(loads, Rot, arm);
    for (int i = 0; i < 6; ++i)
        CHECK(g[i] == doctest::Approx(out[static_cast<std::size_t>(i)]).epsilon(1e-9));
}

TEST_CASE("radiation history: steps shorter than RdtnDT store the same samples; reset forgets") {
    const double dt = 0.1;
    std::vector<double> omega{0.0, 1.0, 2.0, 3.0};
    std::vector<Mat6> damping(4);
    for (std::size_t k = 0; k < 4; ++k) damping[k][0] = 1e4 * (1 + static_cast<double>(k));
    damping[0][0] = 0;
    PotentialFlowSetup s = bare_setup();
    s.kernel_dt = dt;
    s.radiation_kernel = radiation_kernel(omega, damping, dt, 3);
    const auto coarse = potential_flow_block(s), fine = potential_flow_block(s);
    // A surge velocity linear in time: the samples between a step's ends are exact.
    const auto at = [](double t) {
        return frame(Eigen::Vector3d(0.1 * t * t, 0, 0), Eigen::Matrix3d::Identity(),
                     Eigen::Vector3d(0.2 * t + 0.05, 0, 0));
    };
    for (int k = 0; k < 40; ++k) {
        const double t = k * dt, t1 = (k + 1) * dt;
        coarse->update_discrete_states(t, nullptr, at(t).data(), t1, nullptr, at(t1).data());
        for (int m = 0; m < 4; ++m) {
            const double a = t + m * dt / 4, b = t + (m + 1) * dt / 4;
            fine->update_discrete_states(a, nullptr, at(a).data(), b, nullptr, at(b).data());
        }
    }
    const double f = evaluate(*coarse, 4.0, at(4.0)).out[12];
    CHECK(f < -1e2); // a real force
    CHECK(evaluate(*fine, 4.0, at(4.0)).out[12] == doctest::Approx(f).epsilon(1e-12));
    fine->reset_discrete_states();
    // Forgotten: the current velocity alone, -RdtnDT K(0) v.
    CHECK(evaluate(*fine, 4.0, at(4.0)).out[12] ==
          doctest::Approx(-dt * s.radiation_kernel[0][0] * (0.2 * 4.0 + 0.05)).epsilon(1e-12));
}

TEST_CASE(
    "excitation on SeaState's regular wave: a real X gives X times the elevation at the origin") {
    WaveSettings w;
    w.kind = WaveKind::regular;
    w.height = 2.0;
    w.period = 10.0;
    w.t_max = 600;
    w.dt = 0.25;
    w.phase = 0.7;
    w.direction = 0.3;
    const auto field = make_wave_field(w);
    REQUIRE(field->time_step() > 0);
    PotentialFlowSetup s = bare_setup();
    s.excitation.omega = {0.0, 2.0};
    s.excitation.heading = {-pi, pi};
    for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 6; ++i) s.excitation.force.push_back(1e5 * (i + 1));
    s.waves = field;
    const auto block = potential_flow_block(s);
    int checked = 0;
    for (double t = 0; t < 30; t += 1.25) {
        const double eta = field->elevation(t, 0, 0);
        const auto r =
            evaluate(*block, t, frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()));
        for (int i = 0; i < 6; ++i)
            CHECK(r.out[static_cast<std::size_t>(i)] ==
                  doctest::Approx(1e5 * (i + 1) * eta).scale(1e5 * (i + 1)).epsilon(1e-9));
        checked += std::abs(eta) > 0.5;
    }
    CHECK(checked > 5); // the wave is there
}
