// libFuzzer target: a TurbSim input file (formats/wind/turbsim_input.hpp) through
// its reader. Properties: no crash, no sanitizer report; a rejected file throws
// std::runtime_error only, located ("fuzz.inp:line:col: "); an accepted file's
// values are what the generator may take (counts >= 2, positive times and sizes,
// ScaleIEC 0-2, an extreme model with its turbine class), and its warnings are located.
#include "wind/turbsim_input.hpp"

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::istringstream in(text);
    yamsc::wind::TurbSimInput t;
    try {
        t = yamsc::wind::read_turbsim_input(in, "fuzz.inp");
    } catch (const std::runtime_error& e) {
        if (std::string(e.what()).rfind("fuzz.inp:", 0) != 0) std::abort();
        return 0;
    }
    if (t.nz < 2 || t.ny < 2 || !(t.time_step > 0) || !(t.analysis_time > 0) ||
        !(t.usable_time > 0) || !(t.hub_height > 0) || !(t.grid_height > 0) ||
        !(t.grid_width > 0) || !(t.ref_height > 0) || !(t.ref_speed > 0) || !(t.etm_c > 0) ||
        t.scale_iec < 0 || t.scale_iec > 2)
        std::abort();
    if (t.model == yamsc::wind::IecTurbulenceModel::extreme &&
        (t.turbine_class < 1 || t.turbine_class > 3))
        std::abort();
    for (const std::string& w : t.warnings)
        if (w.rfind("fuzz.inp:", 0) != 0) std::abort();
    return 0;
}
