// TurbSim's WrBinTURBSIM (modules/turbsim/src/TS_FileIO.f90), byte for byte:
// per component the slope IntRng / (max - min) and the offset IntMin - slope min,
// both in single precision (a component that does not vary has slope 1), every
// value slope v + offset in single precision, clamped to the int16 range and
// rounded to the nearest integer, halves away from zero (Fortran's NINT). The range
// is taken over the grid and the tower points, as TurbSim takes it over every
// point it wrote.
#include "wind/turbsim_bts.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace yamsc::wind {

namespace {

constexpr float int_max = 32767.0f;
constexpr float int_min = -32768.0f;
constexpr float int_range = int_max - int_min;

// Little-endian whatever the host.
void put_u32(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
}
void put_i16(std::string& out, std::int16_t v) {
    const auto u = static_cast<std::uint16_t>(v);
    out.push_back(static_cast<char>(u & 0xffu));
    out.push_back(static_cast<char>(u >> 8));
}
void put_i32(std::string& out, std::int32_t v) {
    put_u32(out, static_cast<std::uint32_t>(v));
}
void put_f32(std::string& out, float v) {
    std::uint32_t u = 0;
    std::memcpy(&u, &v, 4);
    put_u32(out, u);
}

struct Scaling {
    float slope = 1, offset = 0;
};

Scaling scaling(const FullFieldGrid& g, int component) {
    float lo = 0, hi = 0;
    bool any = false;
    auto visit = [&](const std::vector<float>& values) {
        for (std::size_t i = static_cast<std::size_t>(component); i < values.size(); i += 3) {
            const float v = values[i];
            if (!any) lo = hi = v, any = true;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    };
    visit(g.grid);
    visit(g.tower);
    Scaling s;
    if (hi != lo) s.slope = int_range / (hi - lo);
    s.offset = int_min - s.slope * lo;
    return s;
}

std::int16_t stored(float v, const Scaling& s) {
    const float x = std::max(std::min(s.slope * v + s.offset, int_max), int_min);
    return static_cast<std::int16_t>(std::lround(x));
}

} // namespace

void write_turbsim_bts(std::ostream& out, const FullFieldGrid& g) {
    const std::size_t per_time = static_cast<std::size_t>(g.ny) * g.nz * 3;
    const std::size_t tower_per_time = static_cast<std::size_t>(g.n_tower) * 3;
    if (g.ny < 1 || g.nz < 1 || g.nt < 1 || g.n_tower < 0 ||
        g.grid.size() != per_time * static_cast<std::size_t>(g.nt) ||
        g.tower.size() != tower_per_time * static_cast<std::size_t>(g.nt))
        throw std::runtime_error("TurbSim .bts: the grid's sizes do not match its values");
    Scaling s[3];
    for (int c = 0; c < 3; ++c) s[c] = scaling(g, c);

    std::string header;
    put_i16(header, g.periodic ? 8 : 7);
    put_i32(header, g.nz);
    put_i32(header, g.ny);
    put_i32(header, g.n_tower);
    put_i32(header, g.nt);
    for (double v : {g.dz, g.dy, g.dt, g.u_hub, g.z_hub, g.z_bottom})
        put_f32(header, static_cast<float>(v));
    for (int c = 0; c < 3; ++c) {
        put_f32(header, s[c].slope);
        put_f32(header, s[c].offset);
    }
    put_i32(header, static_cast<std::int32_t>(g.description.size()));
    header += g.description;
    out.write(header.data(), static_cast<std::streamsize>(header.size()));

    std::string block;
    block.reserve((per_time + tower_per_time) * 2);
    for (int it = 0; it < g.nt; ++it) {
        block.clear();
        const float* grid = g.grid.data() + static_cast<std::size_t>(it) * per_time;
        for (std::size_t i = 0; i < per_time; ++i) put_i16(block, stored(grid[i], s[i % 3]));
        const float* tower = g.tower.data() + static_cast<std::size_t>(it) * tower_per_time;
        for (std::size_t i = 0; i < tower_per_time; ++i) put_i16(block, stored(tower[i], s[i % 3]));
        out.write(block.data(), static_cast<std::streamsize>(block.size()));
    }
    if (!out) throw std::runtime_error("TurbSim .bts: cannot write the file");
}

} // namespace yamsc::wind
