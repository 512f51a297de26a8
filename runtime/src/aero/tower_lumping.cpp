// Loads per length on a line mesh as point loads at its nodes (OpenFAST's
// ModMesh_Mapping Lump_Line2_to_Point), the step between AeroDyn's tower load
// mesh and the structure's points.
#include <cmath>

#include "yamsc/aero/tower_influence.hpp"

namespace yamsc::aero {

void lump_line_loads(const Vec3* reference, const Vec3* position, const Vec3* per_length,
                     std::size_t count, Vec3* force, Vec3* moment) {
    for (std::size_t j = 0; j < count; ++j) force[j] = moment[j] = Vec3{};
    for (std::size_t e = 0; e + 1 < count; ++e) {
        const Vec3 &f1 = per_length[e], &f2 = per_length[e + 1];
        double length = 0;
        for (int i = 0; i < 3; ++i)
            length +=
                (reference[e + 1][i] - reference[e][i]) * (reference[e + 1][i] - reference[e][i]);
        const double sixth = std::sqrt(length) / 6;
        const Vec3 dp{position[e + 1][0] - position[e][0], position[e + 1][1] - position[e][1],
                      position[e + 1][2] - position[e][2]};
        const Vec3 sum{f1[0] + f2[0], f1[1] + f2[1], f1[2] + f2[2]};
        const Vec3 couple{sixth / 2 * (dp[1] * sum[2] - dp[2] * sum[1]),
                          sixth / 2 * (dp[2] * sum[0] - dp[0] * sum[2]),
                          sixth / 2 * (dp[0] * sum[1] - dp[1] * sum[0])};
        for (int i = 0; i < 3; ++i) {
            force[e][i] += sixth * (2 * f1[i] + f2[i]);
            force[e + 1][i] += sixth * (f1[i] + 2 * f2[i]);
            moment[e][i] += couple[i];
            moment[e + 1][i] -= couple[i];
        }
    }
}

} // namespace yamsc::aero
