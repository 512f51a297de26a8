#pragma once
// A body frame's 18 mesh outputs at a pose, and a potential-flow setup on them.
#include <yamsc/hydro/potential_flow.hpp>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <vector>

namespace potential_test {

using namespace yamsc::runtime;
using namespace yamsc::runtime::hydro;

/// R = Rx(x) Ry(y) Rz(z): OpenFAST's Tait-Bryan angles (EulerConstruct transposed).
inline Eigen::Matrix3d rotation(double x, double y, double z) {
    return (Eigen::AngleAxisd(x, Eigen::Vector3d::UnitX()) *
            Eigen::AngleAxisd(y, Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(z, Eigen::Vector3d::UnitZ()))
        .toRotationMatrix();
}

inline std::array<double, 18> frame(const Eigen::Vector3d& r, const Eigen::Matrix3d& R,
                                    const Eigen::Vector3d& v = Eigen::Vector3d::Zero(),
                                    const Eigen::Vector3d& w = Eigen::Vector3d::Zero()) {
    std::array<double, 18> f{};
    for (int i = 0; i < 3; ++i) {
        f[static_cast<std::size_t>(i)] = r[i];
        f[static_cast<std::size_t>(3 + i)] = v[i];
        f[static_cast<std::size_t>(6 + i)] = w[i];
        for (int c = 0; c < 3; ++c) f[static_cast<std::size_t>(9 + 3 * c + i)] = R(i, c);
    }
    return f;
}

/// A field of given components, travelling toward `direction`, tabulated on (dt, period).
class ComponentField final : public WaveField {
public:
    ComponentField(std::vector<WaveComponent> c, double direction, double dt, double period)
        : c_(std::move(c)), direction_(direction), dt_(dt), period_(period) {}
    const Water& water() const override { return water_; }
    double elevation(double t, double, double) const override {
        double e = 0;
        for (const WaveComponent& w : c_) e += (w.amplitude * std::polar(1.0, w.omega * t)).real();
        return e;
    }
    FlowAt flow(double, const Vec3&) const override { return {}; }
    const std::vector<WaveComponent>& components() const override { return c_; }
    double direction() const override { return direction_; }
    double period() const override { return period_; }
    double time_step() const override { return dt_; }

private:
    Water water_;
    std::vector<WaveComponent> c_;
    double direction_, dt_, period_;
};

inline PotentialFlowSetup bare_setup() {
    PotentialFlowSetup s;
    for (int i = 0; i < 18; ++i) s.frame_outputs.push_back(i);
    for (int i = 0; i < 6; ++i) s.loads.push_back(i);
    return s;
}

struct Result {
    std::array<double, 6> loads{};
    std::vector<double> out;
};

inline Result evaluate(const LoadBlock& b, double t, const std::array<double, 18>& r) {
    Result res;
    res.out.assign(b.output_names().size(), 0.0);
    b.evaluate(t, nullptr, r.data(), res.loads.data(), nullptr, res.out.data());
    return res;
}

} // namespace potential_test
