// libFuzzer target: a TurbSim `.bts` (formats/wind/turbsim_bts.hpp) through its
// reader. Properties: no crash, no sanitizer report; a rejected file throws
// std::runtime_error only, naming the file and a byte offset within it; an
// accepted one has a grid of 2 x 2 points or more, 2 times or more, as many values
// as its counts say, every value finite, and positive spacings and mean speed.
#include "wind/turbsim_bts.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    yamsc::wind::FullFieldGrid g;
    try {
        g = yamsc::wind::read_turbsim_bts(in, "fuzz.bts");
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        if (what.rfind("fuzz.bts: byte ", 0) != 0) std::abort();
        if (std::stoull(what.substr(15)) > size) std::abort();
        return 0;
    }
    if (g.ny < 2 || g.nz < 2 || g.nt < 2 || g.n_tower < 0) std::abort();
    if (g.grid.size() != std::size_t(g.nt) * g.ny * g.nz * 3) std::abort();
    if (g.tower.size() != std::size_t(g.nt) * g.n_tower * 3) std::abort();
    if (!(g.dy > 0 && g.dz > 0 && g.dt > 0 && g.u_hub > 0)) std::abort();
    for (float v : g.grid)
        if (!std::isfinite(v)) std::abort();
    for (float v : g.tower)
        if (!std::isfinite(v)) std::abort();
    return 0;
}
