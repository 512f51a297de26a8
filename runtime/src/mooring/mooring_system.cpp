#include <yamsc/mooring/mooring_system.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace yamsc::runtime::mooring {
namespace {

Vec3 rotate(const Mat3& r, const Vec3& p) {
    return {r[0] * p[0] + r[1] * p[1] + r[2] * p[2], r[3] * p[0] + r[4] * p[1] + r[5] * p[2],
            r[6] * p[0] + r[7] * p[1] + r[8] * p[2]};
}

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// [a]x, the matrix of a x (.)
Mat3 skew(const Vec3& a) {
    return {0, -a[2], a[1], a[2], 0, -a[0], -a[1], a[0], 0};
}

Mat3 multiply(const Mat3& a, const Mat3& b) {
    Mat3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
    return c;
}

// The force of one line on its fairlead f and its derivative d(force)/d(f).
void line_force(const Line& line, const Vec3& f, const CatenarySolution* guess, LineState& state,
                Mat3& dforce) {
    const double dx = f[0] - line.anchor[0], dy = f[1] - line.anchor[1];
    const double xf = std::hypot(dx, dy);
    state.fairlead = f;
    state.solution = solve_catenary(line.properties, {xf, f[2] - line.anchor[2]}, guess);
    const double h = state.solution.fairlead_horizontal, v = state.solution.fairlead_vertical;
    const double* k = state.solution.stiffness; // d(H, V)/d(x_F, z_F)
    if (xf == 0) throw std::runtime_error("mooring line: the fairlead is right above its anchor");
    const double ex = dx / xf, ey = dy / xf;
    // F = -H e - V z: the line pulls the fairlead towards its anchor and down.
    state.force_on_body = {-h * ex, -h * ey, -v};
    // dH/df = k00 [e, 0] + k01 [0, 0, 1]; de/df = (I - e e^T) / x_F in the plane.
    const double dh[3] = {k[0] * ex, k[0] * ey, k[1]};
    const double dv[3] = {k[2] * ex, k[2] * ey, k[3]};
    const double e[2] = {ex, ey};
    const double p[2][2] = {{1 - ex * ex, -ex * ey}, {-ex * ey, 1 - ey * ey}};
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double de = j < 2 ? p[i][j] / xf : 0;
            dforce[3 * i + j] = -e[i] * dh[j] - h * de;
        }
    }
    for (int j = 0; j < 3; ++j) dforce[6 + j] = -dv[j];
}

} // namespace

double LineState::tension() const {
    return std::hypot(solution.fairlead_horizontal, solution.fairlead_vertical);
}

MooringLoads mooring_loads(const std::vector<Line>& lines, const Pose& pose,
                           const MooringLoads* previous) {
    MooringLoads out;
    out.lines.resize(lines.size());
    const bool warm = previous && previous->lines.size() == lines.size();
    for (std::size_t n = 0; n < lines.size(); ++n) {
        const Vec3 arm = rotate(pose.rotation, lines[n].fairlead);
        const Vec3 f = {pose.position[0] + arm[0], pose.position[1] + arm[1],
                        pose.position[2] + arm[2]};
        LineState& state = out.lines[n];
        line_force(lines[n], f, warm ? &previous->lines[n].solution : nullptr, state,
                   state.force_derivative);
        const Mat3& df = state.force_derivative;
        const Vec3& force = state.force_on_body;
        const Vec3 m = cross(arm, force);
        for (int i = 0; i < 3; ++i) {
            out.force[i] += force[i];
            out.moment[i] += m[i];
        }
        // f = position + arm, d(arm)/d(theta) = -[arm]x; moment = arm x force.
        const Mat3 arm_x = skew(arm);
        const Mat3 df_dtheta =
            multiply(df, Mat3{-arm_x[0], -arm_x[1], -arm_x[2], -arm_x[3], -arm_x[4], -arm_x[5],
                              -arm_x[6], -arm_x[7], -arm_x[8]});
        const Mat3 dm_dpos = multiply(arm_x, df);
        const Mat3 dm_dtheta_force = multiply(skew(force), arm_x); // -(d arm) x force
        const Mat3 dm_dtheta_arm = multiply(arm_x, df_dtheta);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                out.derivative[6 * i + j] += df[3 * i + j];
                out.derivative[6 * i + 3 + j] += df_dtheta[3 * i + j];
                out.derivative[6 * (3 + i) + j] += dm_dpos[3 * i + j];
                out.derivative[6 * (3 + i) + 3 + j] +=
                    dm_dtheta_force[3 * i + j] + dm_dtheta_arm[3 * i + j];
            }
        }
    }
    return out;
}

} // namespace yamsc::runtime::mooring
