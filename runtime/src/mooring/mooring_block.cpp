#include <yamsc/mooring/mooring_block.hpp>

#include <cmath>
#include <stdexcept>

namespace yamsc::runtime::mooring {
namespace {

// The mesh outputs of a body frame: r (0..2), v, w, then the x, y, z axes in
// ground components (9..17), the columns of the rotation body -> ground.
constexpr int axes_at = 9;
constexpr int frame_outputs = 18;

Pose pose_of(const double* r) {
    Pose p;
    for (int i = 0; i < 3; ++i) {
        p.position[static_cast<std::size_t>(i)] = r[i];
        for (int c = 0; c < 3; ++c)
            p.rotation[static_cast<std::size_t>(3 * i + c)] = r[axes_at + 3 * c + i];
    }
    return p;
}

class MooringBlock final : public LoadBlock {
public:
    explicit MooringBlock(MooringSetup s) : setup_(std::move(s)) {
        if (setup_.frame_outputs.size() != frame_outputs || setup_.loads.size() != 6)
            throw std::invalid_argument("mooring block: a body role has 18 frame outputs and "
                                        "6 frame inputs");
        if (setup_.lines.empty()) throw std::invalid_argument("mooring block: no lines");
        ports_.outputs_read = setup_.frame_outputs;
        ports_.loads = setup_.loads;
    }

    const BlockPorts& ports() const override { return ports_; }

    std::vector<std::string> output_names() const override {
        std::vector<std::string> names;
        for (std::size_t n = 1; n <= setup_.lines.size(); ++n)
            names.push_back(setup_.output_prefix + "T_fair" + std::to_string(n));
        for (std::size_t n = 1; n <= setup_.lines.size(); ++n)
            names.push_back(setup_.output_prefix + "T_anch" + std::to_string(n));
        return names;
    }

    void evaluate(double, const double*, const double* r, double* loads, double*,
                  double* out) const override {
        const Pose pose = pose_of(r);
        const MooringLoads m = mooring_loads(setup_.lines, pose);
        to_body_axes(pose, m, loads);
        const std::size_t n = setup_.lines.size();
        for (std::size_t k = 0; k < n; ++k) {
            const CatenarySolution& s = m.lines[k].solution;
            out[k] = m.lines[k].tension();
            out[n + k] = std::hypot(s.anchor_horizontal, s.anchor_vertical);
        }
    }

    // d(R^T F, R^T M)/d(r, axes): the position through each fairlead, the axes
    // through the fairleads' arms (d arm / d R_ic = e_i p_c) and through R^T.
    void derivatives(double, const double*, const double* r, BlockJacobian& j) const override {
        const Pose pose = pose_of(r);
        const MooringLoads m = mooring_loads(setup_.lines, pose);
        const Mat3& R = pose.rotation;
        j.loads_r.assign(6 * frame_outputs, 0.0);
        j.loads_z.clear();
        j.rates_z.clear();
        j.rates_r.clear();
        // Ground-axes derivatives first: dG[row][col], row = force 0..2, moment 3..5.
        double dG[6][frame_outputs] = {};
        for (std::size_t k = 0; k < setup_.lines.size(); ++k) {
            const LineState& s = m.lines[k];
            const Vec3& p = setup_.lines[k].fairlead;
            const Vec3& F = s.force_on_body;
            const Mat3& df = s.force_derivative;
            Vec3 arm;
            for (int i = 0; i < 3; ++i) arm[i] = s.fairlead[i] - pose.position[i];
            auto add_moment = [&](int col, const Vec3& darm, const Vec3& dF) {
                // d(arm x F) = darm x F + arm x dF
                const Vec3 a = {darm[1] * F[2] - darm[2] * F[1], darm[2] * F[0] - darm[0] * F[2],
                                darm[0] * F[1] - darm[1] * F[0]};
                const Vec3 b = {arm[1] * dF[2] - arm[2] * dF[1], arm[2] * dF[0] - arm[0] * dF[2],
                                arm[0] * dF[1] - arm[1] * dF[0]};
                for (int i = 0; i < 3; ++i) dG[3 + i][col] += a[i] + b[i];
            };
            for (int c = 0; c < 3; ++c) { // the fairlead moves with the position
                const Vec3 dF = {df[c], df[3 + c], df[6 + c]};
                for (int i = 0; i < 3; ++i) dG[i][c] += dF[i];
                add_moment(c, {0, 0, 0}, dF);
            }
            for (int c = 0; c < 3; ++c) {     // axis c
                for (int i = 0; i < 3; ++i) { // its ground component i
                    const int col = axes_at + 3 * c + i;
                    Vec3 darm{0, 0, 0};
                    darm[i] = p[c];
                    const Vec3 dF = {df[i] * p[c], df[3 + i] * p[c], df[6 + i] * p[c]};
                    for (int a = 0; a < 3; ++a) dG[a][col] += dF[a];
                    add_moment(col, darm, dF);
                }
            }
        }
        // Body axes: L = R^T G, dL = R^T dG + d(R^T) G, where d(R^T)/dR_ic = e_c e_i^T.
        const Vec3 G[2] = {m.force, m.moment};
        for (int block = 0; block < 2; ++block) {
            for (int col = 0; col < frame_outputs; ++col) {
                for (int row = 0; row < 3; ++row) {
                    double v = 0;
                    for (int i = 0; i < 3; ++i) v += R[3 * i + row] * dG[3 * block + i][col];
                    j.loads_r[static_cast<std::size_t>((3 * block + row) * frame_outputs + col)] =
                        v;
                }
            }
            for (int c = 0; c < 3; ++c)
                for (int i = 0; i < 3; ++i)
                    j.loads_r[static_cast<std::size_t>((3 * block + c) * frame_outputs + axes_at +
                                                       3 * c + i)] += G[block][i];
        }
    }

private:
    static void to_body_axes(const Pose& pose, const MooringLoads& m, double* loads) {
        const Mat3& R = pose.rotation;
        for (int row = 0; row < 3; ++row) {
            loads[row] = R[row] * m.force[0] + R[3 + row] * m.force[1] + R[6 + row] * m.force[2];
            loads[3 + row] =
                R[row] * m.moment[0] + R[3 + row] * m.moment[1] + R[6 + row] * m.moment[2];
        }
    }

    MooringSetup setup_;
    BlockPorts ports_;
};

} // namespace

std::shared_ptr<const LoadBlock> mooring_block(MooringSetup setup) {
    return std::make_shared<const MooringBlock>(std::move(setup));
}

} // namespace yamsc::runtime::mooring
