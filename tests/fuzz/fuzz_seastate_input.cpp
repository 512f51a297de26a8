// libFuzzer target: a SeaState input file through seastate::read_seastate_input.
// Properties: no crash, no sanitizer report, no exception; a rejected file reports an
// error; an accepted file's point lists have the lengths NWaveElev and NWaveKin give
// (at most 9) and its grid counts are within their limits.
#include "seastate/seastate_input.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    auto file = std::make_shared<const diag::SourceFile>(
        "fuzz.dat", std::string(reinterpret_cast<const char*>(data), size));
    diag::Diagnostics diags;
    const auto in = seastate::read_seastate_input(file, diags, aerodyn::includes_refused());
    (void)diags.render();
    if (!in) {
        if (!diags.has_errors()) std::abort();
        return 0;
    }
    const auto limit = static_cast<std::size_t>(seastate::max_points);
    if (in->wave_elev_x.size() != in->wave_elev_y.size() || in->wave_elev_x.size() > limit ||
        in->wave_kin_x.size() != in->wave_kin_y.size() ||
        in->wave_kin_x.size() != in->wave_kin_z.size() || in->wave_kin_x.size() > limit)
        std::abort();
    for (int g : {in->nx, in->ny, in->nz})
        if (g < 2 || g > seastate::max_grid_nodes) std::abort();
    if (in->out_channel_lines.size() != in->out_channels.size()) std::abort();
    return 0;
}
