#pragma once
// The frozen-wake linear model with AeroDyn's dynamic inflow put back: the
// relief the wake gives (the quasi-steady linear model less the frozen one)
// passed through DBEMT's two stages (Oye's filter), so that the tower's
// damping of a decay with dynamic inflow can be explained from two `lin`s.
// Models of one fixed DOF and one mode per blade (tower FA1 and flap 1), as
// `lin --format openfast-lin --mbc3` writes them per azimuth.
#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <fstream>
#include <string>

namespace linear_test {

/// State matrix, azimuth and rotor speed of one OpenFAST .lin file.
struct LinFile {
    Eigen::MatrixXd a;
    double azimuth = 0, rotor_speed = 0;
};

inline LinFile read_lin_file(const std::string& path) {
    std::ifstream in(path);
    LinFile f;
    std::string line;
    auto value = [&] { return std::stod(line.substr(line.find(':') + 1)); };
    while (std::getline(in, line)) {
        if (line.find("Rotor Speed:") != std::string::npos) f.rotor_speed = value();
        if (line.rfind("   Azimuth:", 0) == 0) f.azimuth = value();
        if (line.rfind("A: ", 0) == 0) {
            const int n = std::stoi(line.substr(3));
            f.a.resize(n, n);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) in >> f.a(i, j);
            break;
        }
    }
    return f;
}

/// The state matrix in the fixed frame (Coleman's transform of the three
/// blades' coordinates, states [q_fa, q_b1..3, q_fa', q_b1..3']) at one
/// azimuth of blade 1.
inline Eigen::MatrixXd fixed_frame(const LinFile& f) {
    constexpr double pi = 3.14159265358979323846;
    const double w = f.rotor_speed;
    Eigen::Matrix4d t = Eigen::Matrix4d::Zero(), td = t, tdd = t;
    t(0, 0) = 1;
    for (int b = 0; b < 3; ++b) {
        const double p = f.azimuth + 2 * pi * b / 3, c = std::cos(p), s = std::sin(p);
        t.row(1 + b) << 0, 1, c, s;
        td.row(1 + b) << 0, 0, -w * s, w * c;
        tdd.row(1 + b) << 0, 0, -w * w * c, -w * w * s;
    }
    Eigen::MatrixXd t1 = Eigen::MatrixXd::Zero(8, 8), t1d = t1;
    t1.block<4, 4>(0, 0) = t;
    t1.block<4, 4>(4, 4) = t;
    t1.block<4, 4>(4, 0) = td;
    t1d.block<4, 4>(0, 0) = td;
    t1d.block<4, 4>(4, 4) = td;
    t1d.block<4, 4>(4, 0) = tdd;
    return t1.inverse() * (f.a * t1 - t1d);
}

/// The frozen model's states with Oye's filter on the relief D x
/// (D = a_quasi_steady - a_frozen): x' = A x + v2,
/// tau1 w' = (1 - k) D x - w, tau2 v2' = w + k D x - v2 (AeroDyn's DBEMT, k 0.6).
inline Eigen::MatrixXd with_filtered_relief(const Eigen::MatrixXd& frozen,
                                            const Eigen::MatrixXd& quasi_steady, double tau1,
                                            double tau2) {
    constexpr double k = 0.6;
    const Eigen::Index n = frozen.rows();
    const Eigen::MatrixXd d = quasi_steady - frozen, id = Eigen::MatrixXd::Identity(n, n);
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    a.block(0, 0, n, n) = frozen;
    a.block(0, 2 * n, n, n) = id;
    a.block(n, 0, n, n) = (1 - k) / tau1 * d;
    a.block(n, n, n, n) = -id / tau1;
    a.block(2 * n, 0, n, n) = k / tau2 * d;
    a.block(2 * n, n, n, n) = id / tau2;
    a.block(2 * n, 2 * n, n, n) = -id / tau2;
    return a;
}

/// Damping ratio of the eigenvalue whose natural frequency is nearest
/// freq_hz (within 10 %; NaN if none).
inline double damping_near(const Eigen::MatrixXd& a, double freq_hz) {
    constexpr double pi = 3.14159265358979323846;
    const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(a).eigenvalues();
    double best = 0.1 * freq_hz, zeta = std::nan("");
    for (Eigen::Index i = 0; i < ev.size(); ++i) {
        const double f = std::abs(ev[i]) / (2 * pi);
        if (ev[i].imag() > 0 && std::abs(f - freq_hz) < best) {
            best = std::abs(f - freq_hz);
            zeta = -ev[i].real() / std::abs(ev[i]);
        }
    }
    return zeta;
}

} // namespace linear_test
