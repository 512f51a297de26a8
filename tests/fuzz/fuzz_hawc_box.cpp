// libFuzzer target: a HAWC box component (formats/wind/hawc_box.hpp) through its
// reader. The input's first three bytes give nx, ny, nz (1 to 16 each: the
// InflowWind file's entries), the rest is the component's file. Properties: no
// crash, no sanitizer report; a short file throws std::runtime_error naming the
// file and a byte offset within it; an accepted one fills every value of its
// component with a finite number and leaves the other components alone.
#include "wind/hawc_box.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 3) return 0;
    const int nx = data[0] % 16 + 1, ny = data[1] % 16 + 1, nz = data[2] % 16 + 1;
    const std::string file(reinterpret_cast<const char*>(data) + 3, size - 3);
    std::istringstream in(file);
    const float unset = -12345.0f;
    std::vector<float> grid(std::size_t(nx) * ny * nz * 3, unset);
    try {
        yamsc::wind::read_hawc_component(in, "fuzz.bin", nx, ny, nz, 1, grid);
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        if (what.rfind("fuzz.bin: byte ", 0) != 0) std::abort();
        if (std::stoull(what.substr(15)) > file.size()) std::abort();
        return 0;
    }
    for (std::size_t i = 0; i < grid.size(); ++i) {
        if (i % 3 == 1 ? !std::isfinite(grid[i]) : grid[i] != unset) std::abort();
    }
    return 0;
}
