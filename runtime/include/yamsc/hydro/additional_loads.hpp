#pragma once
// HydroDyn's additional platform loads (AddF0, AddCLin, AddBLin, AddBQuad) on the
// displacement of the platform reference point (the WAMIT body's point,
// PtfmRefxt/yt/zt), exactly as HydroDyn applies them (HydroDyn.f90, with
// PotMod 1 only): F = F0 - C q - R B_lin R^T q' - R B_quad |R^T q'| (R^T q'),
// q = (translation of the point, intrinsic x-y-z Tait-Bryan angles of its
// orientation: OpenFAST's EulerExtract), q' = (its velocity, the angular
// velocity), all in ground axes; R the body's axes in ground components. F and
// C are in ground axes, the damping matrices in body axes.
#include <yamsc/load_block.hpp>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace yamsc::runtime::hydro {

using Vec3 = std::array<double, 3>;
using Mat6 = std::array<double, 36>; // row-major

struct PlatformMatrices {
    std::array<double, 6> f0{};
    Mat6 c_lin{}, b_lin{}, b_quad{};
};

/// The reference point's pose and motion, as HydroDyn's WAMIT mesh gives it.
struct PlatformMotion {
    std::array<double, 6> q{};  // displacement, Tait-Bryan angles (EulerExtract)
    std::array<double, 6> qd{}; // velocity, angular velocity (ground axes)
    std::array<double, 9> R{};  // body axes in ground components, row-major
};

/// The additional load (force, moment about the displaced point; ground axes).
std::array<double, 6> platform_matrices_load(const PlatformMatrices& m, const PlatformMotion& s);

/// A block applying them alone on a body's mesh (18 frame outputs, 6 loads at the
/// body origin in body axes); `reference` in HydroDyn's global coordinates,
/// `origin_at_rest` where the body origin is with every DOF zero. Outputs:
/// <prefix>AddFxi ... <prefix>AddMzi (HydroDyn's B1AddFxi ...).
std::shared_ptr<const LoadBlock> platform_matrices_block(PlatformMatrices matrices, Vec3 reference,
                                                         Vec3 origin_at_rest,
                                                         std::vector<int> frame_outputs,
                                                         std::vector<int> loads,
                                                         std::string output_prefix = "B1");

} // namespace yamsc::runtime::hydro
