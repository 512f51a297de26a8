#pragma once
// TurbSim's full-field binary file (`.bts`, TurbSim's WrBinTURBSIM, read by
// InflowWind's IfW_TurbSim for WindType 3): a grid of ny x nz points in the
// rotor plane, optionally a column of tower points below it, and nt times.
//
// The file, little-endian throughout:
//   int16   id              8: periodic in time, 7: not periodic
//   int32   nz, ny, n_tower, nt
//   float32 dz, dy, dt, u_hub, z_hub, z_bottom
//   float32 slope, offset of u, then of v, then of w  (value = (stored - offset) / slope)
//   int32   n_chars, then n_chars bytes of description
//   per time: for iz, for iy: u, v, w as int16 (iy fastest); then for each
//   tower point (from the grid's bottom down): u, v, w as int16.
// The grid's y runs from -(ny - 1) dy / 2 to +(ny - 1) dy / 2 about the hub (TurbSim
// centres it), z from z_bottom up by dz; the tower points are at y = 0, from
// z_bottom down by dz.
//
// The values are kept as the file's 16-bit integers' decoded floats, in the
// file's axes (u along the mean wind, v to its left, w up).
#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace yamsc::wind {

struct FullFieldGrid {
    int ny = 0, nz = 0, n_tower = 0, nt = 0;
    double dy = 0, dz = 0, dt = 0;
    double u_hub = 0;    // the mean speed at the hub height [m/s]
    double z_hub = 0;    // [m], from the ground
    double z_bottom = 0; // the grid's lowest row [m], from the ground
    bool periodic = false;
    std::string description;
    /// [((it * nz + iz) * ny + iy) * 3 + component]
    std::vector<float> grid;
    /// [(it * n_tower + k) * 3 + component], k = 0 just below the grid
    std::vector<float> tower;

    float at(int it, int iz, int iy, int component) const {
        return grid[((static_cast<std::size_t>(it) * nz + iz) * ny + iy) * 3 + component];
    }
    float tower_at(int it, int k, int component) const {
        return tower[(static_cast<std::size_t>(it) * n_tower + k) * 3 + component];
    }
};

/// Reads a `.bts` file. Throws std::runtime_error "source: what" (with the byte
/// offset where the file is short or a count is impossible).
FullFieldGrid read_turbsim_bts(std::istream& in, const std::string& source);

/// Writes `grid` as TurbSim does: per component the slope and offset that map
/// the component's range onto the int16 range (TurbSim's IntRng), then the
/// rounded integers. Throws std::runtime_error if the stream fails.
void write_turbsim_bts(std::ostream& out, const FullFieldGrid& grid);

} // namespace yamsc::wind
