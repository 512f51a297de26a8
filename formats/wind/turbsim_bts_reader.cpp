// TurbSim's `.bts` read as InflowWind's IfW_TurbSim_Init reads it: the header,
// the description, then per time the grid and the tower points, each value
// (stored - offset) / slope in single precision.
#include "wind/turbsim_bts.hpp"

#include "wind/binary_reader.hpp"

#include <cmath>
#include <cstring>

namespace yamsc::wind {

namespace {

/// The largest grid read (values per component and time, times): far beyond
/// any TurbSim run, small enough that a count cannot overflow a size.
constexpr std::int64_t max_points = 1 << 24;
constexpr std::int64_t max_times = 1 << 28;
constexpr std::int64_t max_values = std::int64_t(1) << 34;
constexpr std::int32_t max_description = 1 << 20;

} // namespace

FullFieldGrid read_turbsim_bts(std::istream& in, const std::string& source) {
    BinaryReader b(in, source);
    FullFieldGrid g;
    const std::int16_t id = b.get<std::int16_t>("the header");
    if (id != 7 && id != 8)
        b.fail(0, "file id " + std::to_string(id) +
                      ": not a TurbSim full-field file (7: not periodic, 8: periodic)");
    g.periodic = id == 8;
    struct Count {
        int* to;
        const char* name;
        int least;
        std::int64_t most;
    };
    for (const Count& c : {Count{&g.nz, "the grid's points in z", 2, max_points},
                           Count{&g.ny, "the grid's points in y", 2, max_points},
                           Count{&g.n_tower, "the tower points", 0, max_points},
                           Count{&g.nt, "the times", 2, max_times}}) {
        const std::uint64_t at = b.offset();
        const std::int32_t v = b.get<std::int32_t>("the header");
        if (v < c.least || v > c.most)
            b.fail(at, std::string(c.name) + ": " + std::to_string(v) + " (expected " +
                           std::to_string(c.least) + " to " + std::to_string(c.most) + ")");
        *c.to = v;
    }
    if (std::int64_t(g.ny) * g.nz + g.n_tower > max_points)
        b.fail(2, "a grid of " + std::to_string(g.ny) + " x " + std::to_string(g.nz) + " and " +
                      std::to_string(g.n_tower) + " tower points is too large");
    struct Real {
        double* to;
        const char* name;
        bool positive;
    };
    for (const Real& r :
         {Real{&g.dz, "dz", true}, Real{&g.dy, "dy", true}, Real{&g.dt, "dt", true},
          Real{&g.u_hub, "the hub's mean speed", true}, Real{&g.z_hub, "the hub's height", false},
          Real{&g.z_bottom, "the grid's bottom", false}}) {
        const std::uint64_t at = b.offset();
        const float v = b.get<float>("the header");
        if (!std::isfinite(v) || (r.positive && !(v > 0)))
            b.fail(at, std::string(r.name) + ": " + std::to_string(v) +
                           (r.positive ? " (expected a positive number)" : " (not a number)"));
        *r.to = v;
    }
    float slope[3], offset[3];
    for (int c = 0; c < 3; ++c) {
        const std::uint64_t at = b.offset();
        slope[c] = b.get<float>("the header");
        offset[c] = b.get<float>("the header");
        if (!std::isfinite(slope[c]) || slope[c] == 0 || !std::isfinite(offset[c]))
            b.fail(at, std::string("the scaling of ") + "uvw"[c] + ": slope " +
                           std::to_string(slope[c]) + ", offset " + std::to_string(offset[c]) +
                           " (expected a non-zero slope and finite numbers)");
    }
    const std::uint64_t at_chars = b.offset();
    const std::int32_t n_chars = b.get<std::int32_t>("the header");
    if (n_chars < 0 || n_chars > max_description)
        b.fail(at_chars, "description of " + std::to_string(n_chars) + " characters");
    b.require(static_cast<std::uint64_t>(n_chars), "the description");
    g.description.resize(static_cast<std::size_t>(n_chars));
    b.read(g.description.data(), g.description.size(), "the description");

    const std::int64_t grid_values = std::int64_t(g.nt) * g.ny * g.nz * 3;
    const std::int64_t tower_values = std::int64_t(g.nt) * g.n_tower * 3;
    if (grid_values + tower_values > max_values)
        b.fail(at_chars, std::to_string(g.nt) + " times of " + std::to_string(g.ny) + " x " +
                             std::to_string(g.nz) + " points are too many");
    b.require(2 * static_cast<std::uint64_t>(grid_values + tower_values), "the velocities");
    // Grown as times are read: a stream that cannot tell its size gets no more
    // memory than the data it holds.
    if (b.sized()) {
        g.grid.reserve(static_cast<std::size_t>(grid_values));
        g.tower.reserve(static_cast<std::size_t>(tower_values));
    }

    // One time at once: grid then tower, components fastest (u, v, w).
    const std::size_t per_grid = static_cast<std::size_t>(g.ny) * g.nz * 3;
    const std::size_t per_tower = static_cast<std::size_t>(g.n_tower) * 3;
    std::vector<unsigned char> raw(2 * (per_grid + per_tower));
    // `at`: the byte offset of `from` (a value the scaling makes infinite fails there).
    auto decode = [&](const unsigned char* from, std::size_t n, float* to, std::uint64_t at) {
        for (std::size_t i = 0; i < n; ++i) {
            const auto u = static_cast<std::uint16_t>(from[2 * i] | (from[2 * i + 1] << 8));
            std::int16_t v;
            std::memcpy(&v, &u, 2);
            const std::size_t c = i % 3;
            to[i] = (static_cast<float>(v) - offset[c]) / slope[c];
            if (!std::isfinite(to[i])) b.fail(at + 2 * i, "the scaling makes the value infinite");
        }
    };
    for (int it = 0; it < g.nt; ++it) {
        const std::uint64_t at = b.offset();
        b.read(raw.data(), raw.size(), "the velocities");
        g.grid.resize(g.grid.size() + per_grid);
        g.tower.resize(g.tower.size() + per_tower);
        decode(raw.data(), per_grid, g.grid.data() + it * per_grid, at);
        decode(raw.data() + 2 * per_grid, per_tower, g.tower.data() + it * per_tower,
               at + 2 * per_grid);
    }
    return g;
}

} // namespace yamsc::wind
