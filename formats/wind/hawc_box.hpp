#pragma once
// A HAWC turbulence box (InflowWind WindType 5): one file per component (u, v,
// w), nx planes along x, each ny x nz float32 values, little-endian, z fastest
// and y from +y down to -y (HAWC2's y points the other way), no header; nx, ny,
// nz come from the InflowWind file (IfW_HAWC_Init reads it so). Bytes after the
// last plane are not read (as InflowWind's).
#include <istream>
#include <string>
#include <vector>

namespace yamsc::wind {

/// The largest box read (points per component): far beyond any HAWC2 box, small
/// enough that no size overflows.
inline constexpr long long max_hawc_points = 1LL << 31;

/// Reads component `component` (0: u, 1: v, 2: w) of an nx x ny x nz box into
/// `grid`, laid out as FullFieldGrid's (turbsim_bts.hpp) with the planes as its
/// times: grid[((ix * nz + iz) * ny + iy) * 3 + component], y rising with iy.
/// `grid` must hold nx * ny * nz * 3 values. Throws std::runtime_error
/// "source: byte N: what" on a short file, std::invalid_argument on counts
/// below 1 or above max_hawc_points.
void read_hawc_component(std::istream& in, const std::string& source, int nx, int ny, int nz,
                         int component, std::vector<float>& grid);

} // namespace yamsc::wind
