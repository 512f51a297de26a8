// The .bts writer (formats/wind/turbsim_bts_writer.cpp) against TurbSim's
// WrBinTURBSIM: the header's bytes as TurbSim wrote them for the reference file
// (U18_s1.bts), the per-component scaling and Fortran's NINT rounding.
#include "analysis/turbulence_spec.hpp"
#include "wind/turbsim_bts.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

using yamsc::wind::FullFieldGrid;

namespace {

FullFieldGrid grid_of(int ny, int nz, int nt, int n_tower = 0) {
    FullFieldGrid g;
    g.ny = ny;
    g.nz = nz;
    g.nt = nt;
    g.n_tower = n_tower;
    g.dy = g.dz = 1;
    g.dt = 0.05;
    g.u_hub = 10;
    g.z_hub = 50;
    g.z_bottom = 40;
    g.grid.assign(static_cast<std::size_t>(ny) * nz * nt * 3, 0.0f);
    g.tower.assign(static_cast<std::size_t>(n_tower) * nt * 3, 0.0f);
    return g;
}

std::string written(const FullFieldGrid& g) {
    std::ostringstream out;
    yamsc::wind::write_turbsim_bts(out, g);
    return out.str();
}

std::uint32_t u32_at(const std::string& s, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(s[at + i]);
    return v;
}
float f32_at(const std::string& s, std::size_t at) {
    const std::uint32_t u = u32_at(s, at);
    float f = 0;
    std::memcpy(&f, &u, 4);
    return f;
}
std::int16_t i16_at(const std::string& s, std::size_t at) {
    return static_cast<std::int16_t>(static_cast<unsigned char>(s[at]) |
                                     static_cast<unsigned char>(s[at + 1]) << 8);
}

// id, counts, then 6 floats, 6 scaling floats, the description's length: 70 bytes.
constexpr std::size_t data_start = 2 + 4 * 4 + 6 * 4 + 6 * 4 + 4;

} // namespace

// xxd of TurbSim's U18_s1.bts: id 7, nz 15, ny 15, no tower, 7362 steps, dz = dy =
// 145/14, 0.05 s, 18 m/s, 90 m, bottom 17.5 m.
const unsigned char turbsim[42] = {0x07, 0x00, 0x0f, 0x00, 0x00, 0x00, 0x0f, 0x00, 0x00, 0x00, 0x00,
                                   0x00, 0x00, 0x00, 0xc2, 0x1c, 0x00, 0x00, 0xdb, 0xb6, 0x25, 0x41,
                                   0xdb, 0xb6, 0x25, 0x41, 0xcd, 0xcc, 0x4c, 0x3d, 0x00, 0x00, 0x90,
                                   0x41, 0x00, 0x00, 0xb4, 0x42, 0x00, 0x00, 0x8c, 0x41};

TEST_CASE("the header's first 42 bytes as TurbSim wrote U18_s1.bts") {
    // The bytes above are the file's, where the file is (the full-field reader's
    // tests keep it beside U18_s1.inp).
    std::ifstream file(std::string(YAMSC_TEST_DATA_DIR) + "/reference/turbulence/U18_s1.bts",
                       std::ios::binary);
    if (file) {
        char head[sizeof turbsim] = {};
        file.read(head, sizeof head);
        CHECK(std::memcmp(head, turbsim, sizeof turbsim) == 0);
    }
    FullFieldGrid g = grid_of(15, 15, 7362);
    g.dy = g.dz = 145.0 / 14;
    g.u_hub = 18;
    g.z_hub = 90;
    g.z_bottom = 17.5;
    const std::string s = written(g);
    CHECK(std::memcmp(s.data(), turbsim, sizeof turbsim) == 0);
    CHECK(s.size() == data_start + 15u * 15 * 7362 * 3 * 2);
}

TEST_CASE("U18_s1.inp's layout, written, gives the header TurbSim wrote from it") {
    yamsc::driver::TurbulenceOptions o;
    o.input = std::string(YAMSC_TEST_DATA_DIR) + "/reference/turbulence/U18_s1.inp";
    std::vector<std::string> warnings;
    const yamsc::runtime::TurbulenceSpec s = yamsc::analysis::turbulence_spec(o, warnings);
    const yamsc::runtime::TurbulenceLayout l = yamsc::runtime::turbulence_layout(s);
    FullFieldGrid g = grid_of(s.ny, s.nz, l.steps_written);
    g.dy = l.dy;
    g.dz = l.dz;
    g.dt = s.time_step;
    g.u_hub = yamsc::runtime::iec_parameters(s).u_hub;
    g.z_hub = s.hub_height;
    g.z_bottom = l.z_bottom;
    g.periodic = s.periodic;
    CHECK(std::memcmp(written(g).data(), turbsim, sizeof turbsim) == 0);
}

TEST_CASE("per component IntRng / (max - min) and IntMin - slope min; NINT halves away from 0") {
    FullFieldGrid g = grid_of(2, 1, 2, 1);
    g.periodic = true;
    g.description = "yamsc";
    // u: 0 .. 65535 gives slope 1, offset -32768: 0.5 -> -32767.5 -> -32768 and
    // 1.5 -> -32766.5 -> -32767 (round half to even would give -32766).
    const float u[] = {0.0f, 65535.0f, 0.5f, 1.5f};
    for (int i = 0; i < 4; ++i) g.grid[static_cast<std::size_t>(i) * 3] = u[i];
    for (int i = 0; i < 4; ++i)
        g.grid[static_cast<std::size_t>(i) * 3 + 1] = -2.0f + i;                    // v: -2 .. 1
    for (int i = 0; i < 4; ++i) g.grid[static_cast<std::size_t>(i) * 3 + 2] = 3.0f; // w: constant
    g.tower = {100.0f, -3.0f, 3.0f, -1.0f, 2.0f, 3.0f}; // the tower's range counts too
    const std::string s = written(g);
    CHECK(i16_at(s, 0) == 8);
    const float u_slope = 65535.0f / (65535.0f - -1.0f);
    CHECK(f32_at(s, 42) == u_slope);
    CHECK(f32_at(s, 46) == -32768.0f - u_slope * -1.0f);
    CHECK(f32_at(s, 50) == 65535.0f / 5.0f); // v: -3 (tower) .. 2 (tower)
    CHECK(f32_at(s, 54) == -32768.0f - 65535.0f / 5.0f * -3.0f);
    CHECK(f32_at(s, 58) == 1.0f); // w constant: slope 1, offset IntMin - w
    CHECK(f32_at(s, 62) == -32768.0f - 3.0f);
    CHECK(u32_at(s, 66) == 5);
    CHECK(s.substr(70, 5) == "yamsc");
    const std::size_t at = data_start + 5;
    // time 0: grid (0, 0), (1, 0), then the tower point
    CHECK(i16_at(s, at + 2) == -32768 + 13107); // v = -2: (-2 + 3) 65535/5 = 13107
    CHECK(i16_at(s, at + 4) == -32768);         // w
    CHECK(i16_at(s, at + 6) == 32767);          // u = 65535, the maximum
    CHECK(i16_at(s, at + 12) == -32667);        // the tower's u = 100: 101 u_slope - 32768
    CHECK(i16_at(s, at + 14) == -32768);        // the tower's v = -3, the minimum
    CHECK(s.size() == data_start + 5 + 2 * 3 * 3 * 2);

    FullFieldGrid exact = grid_of(2, 1, 2);
    for (int i = 0; i < 4; ++i) exact.grid[static_cast<std::size_t>(i) * 3] = u[i];
    const std::string e = written(exact);
    CHECK(i16_at(e, data_start + 0) == -32768);
    CHECK(i16_at(e, data_start + 6) == 32767);
    CHECK(i16_at(e, data_start + 12) == -32768);
    CHECK(i16_at(e, data_start + 18) == -32767);
}

TEST_CASE("a grid whose values do not match its counts is refused") {
    FullFieldGrid g = grid_of(2, 2, 3);
    g.grid.pop_back();
    std::ostringstream out;
    CHECK_THROWS_AS(yamsc::wind::write_turbsim_bts(out, g), std::runtime_error);
}
