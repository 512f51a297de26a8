#pragma once
// SeaState's wave elevation channels (Wave1Elev, Wave2Elev, ...) as a block
// with outputs only: the field's elevation at fixed points of the still-water
// plane, which do not move with the platform. It reads nothing and loads nothing.
#include <yamsc/hydro/waves.hpp>
#include <yamsc/load_block.hpp>

#include <memory>
#include <string>
#include <vector>

namespace yamsc::runtime::hydro {

struct ElevationPoint {
    double x = 0, y = 0; // ground axes [m]
};

/// Outputs <prefix>Wave<k>Elev [m], k = 1 .. points.size(); a null field is still
/// water. Throws std::invalid_argument without points.
std::shared_ptr<const LoadBlock> wave_elevation_block(std::shared_ptr<const WaveField> field,
                                                      std::vector<ElevationPoint> points,
                                                      std::string output_prefix);

} // namespace yamsc::runtime::hydro
