#include "wind/hawc_box.hpp"

#include "wind/binary_reader.hpp"

#include <cmath>
#include <stdexcept>

namespace yamsc::wind {

void read_hawc_component(std::istream& in, const std::string& source, int nx, int ny, int nz,
                         int component, std::vector<float>& grid) {
    if (nx < 1 || ny < 1 || nz < 1 || component < 0 || component > 2 ||
        static_cast<long long>(nx) * ny * nz > max_hawc_points)
        throw std::invalid_argument("HAWC box: " + std::to_string(nx) + " x " + std::to_string(ny) +
                                    " x " + std::to_string(nz) +
                                    " points (expected 1 or more each, " +
                                    std::to_string(max_hawc_points) + " in all at most)");
    const std::size_t plane = static_cast<std::size_t>(ny) * nz;
    if (grid.size() != plane * nx * 3)
        throw std::invalid_argument("HAWC box: the grid does not hold the box");
    BinaryReader b(in, source);
    b.require(4 * plane * nx, "the box");
    std::vector<unsigned char> raw(4 * plane);
    for (int ix = 0; ix < nx; ++ix) {
        b.read(raw.data(), raw.size(), "the box");
        for (int iyf = 0; iyf < ny; ++iyf)
            for (int iz = 0; iz < nz; ++iz) {
                const unsigned char* p = raw.data() + 4 * (std::size_t(iyf) * nz + iz);
                const std::uint32_t u = std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 |
                                        std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
                float v;
                std::memcpy(&v, &u, 4);
                if (!std::isfinite(v))
                    b.fail(b.offset() - raw.size() + (p - raw.data()), "not a number");
                const int iy = ny - 1 - iyf;
                grid[((std::size_t(ix) * nz + iz) * ny + iy) * 3 + component] = v;
            }
    }
}

} // namespace yamsc::wind
