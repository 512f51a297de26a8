#include <yamsc/hydro/additional_loads.hpp>

#include "platform_point.hpp"

#include <cmath>
#include <stdexcept>

namespace yamsc::runtime::hydro {

std::array<double, 6> platform_matrices_load(const PlatformMatrices& m, const PlatformMotion& s) {
    using detail::Vector6;
    const Eigen::Map<const Eigen::Matrix3d> Rt(s.R.data()); // row-major R read column-major: R^T
    Eigen::Matrix<double, 6, 6> g2b = Eigen::Matrix<double, 6, 6>::Zero();
    g2b.topLeftCorner<3, 3>() = Rt;
    g2b.bottomRightCorner<3, 3>() = Rt;
    const Vector6 q = Eigen::Map<const Vector6>(s.q.data());
    const Vector6 qd_body = g2b * Eigen::Map<const Vector6>(s.qd.data());
    const Vector6 qd_sq = qd_body.cwiseAbs().cwiseProduct(qd_body);
    const Vector6 f = Eigen::Map<const Vector6>(m.f0.data()) - detail::to_eigen(m.c_lin) * q -
                      g2b.transpose() * (detail::to_eigen(m.b_lin) * qd_body +
                                         detail::to_eigen(m.b_quad) * qd_sq);
    std::array<double, 6> out{};
    for (int i = 0; i < 6; ++i) out[static_cast<std::size_t>(i)] = f[i];
    return out;
}

namespace {

const char* const components[6] = {"Fxi", "Fyi", "Fzi", "Mxi", "Myi", "Mzi"};

class PlatformMatricesBlock final : public LoadBlock {
public:
    PlatformMatricesBlock(PlatformMatrices m, Vec3 reference, Vec3 origin, std::vector<int> frame,
                          std::vector<int> loads, std::string prefix)
        : m_(m), reference_(reference), origin_(origin), prefix_(std::move(prefix)) {
        if (frame.size() != 18 || loads.size() != 6)
            throw std::invalid_argument("platform matrices: a body role has 18 frame outputs and "
                                        "6 frame inputs");
        ports_.outputs_read = std::move(frame);
        ports_.loads = std::move(loads);
    }
    const BlockPorts& ports() const override { return ports_; }
    std::vector<std::string> output_names() const override {
        std::vector<std::string> n;
        for (const char* c : components) n.push_back(prefix_ + "Add" + c);
        return n;
    }
    void evaluate(double, const double*, const double* r, double* loads, double*,
                  double* out) const override {
        const detail::PointState s = detail::point_state(r, reference_, origin_);
        const std::array<double, 6> f = platform_matrices_load(m_, s.motion);
        for (int i = 0; i < 6; ++i) loads[i] = 0;
        detail::to_body_loads(s, Eigen::Map<const detail::Vector6>(f.data()), loads);
        for (int i = 0; i < 6; ++i) out[i] = f[static_cast<std::size_t>(i)];
    }

private:
    PlatformMatrices m_;
    Vec3 reference_, origin_;
    std::string prefix_;
    BlockPorts ports_;
};

} // namespace

std::shared_ptr<const LoadBlock> platform_matrices_block(PlatformMatrices matrices, Vec3 reference,
                                                         Vec3 origin_at_rest,
                                                         std::vector<int> frame_outputs,
                                                         std::vector<int> loads,
                                                         std::string output_prefix) {
    return std::make_shared<const PlatformMatricesBlock>(matrices, reference, origin_at_rest,
                                                         std::move(frame_outputs), std::move(loads),
                                                         std::move(output_prefix));
}

} // namespace yamsc::runtime::hydro
