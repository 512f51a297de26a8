// libFuzzer target: an InflowWind primary file (formats/wind/inflowwind_file.hpp)
// through its reader and the accessors the wind kinds use. Properties: no crash,
// no sanitizer report; a rejected file or value throws std::runtime_error only; an
// accepted file has a WindType entry, and every entry and warning is located.
#include "wind/inflowwind_file.hpp"

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::istringstream head(text);
    // The guess `--wind` makes; the reader decides either way.
    static_cast<void>(yamsc::wind::looks_like_inflowwind(head));
    std::istringstream in(text);
    yamsc::wind::InflowWindFile f;
    try {
        f = yamsc::wind::read_inflowwind_file(in, "fuzz.dat");
    } catch (const std::runtime_error&) {
        return 0;
    }
    if (!f.find("WindType")) std::abort();
    for (const yamsc::wind::InflowWindEntry& e : f.entries)
        if (e.line < 4 || e.key.empty() || e.values.size() != e.columns.size()) std::abort();
    for (const std::string& w : f.warnings)
        if (w.rfind("fuzz.dat:", 0) != 0) std::abort();
    for (const char* key : {"WindType", "PropagationDir", "VFlowAng", "HWindSpeed", "RefHt",
                            "PLexp", "FileName_Uni", "RefHt_Uni", "RefLength", "NWindVel",
                            "SensorType", "Echo", "VelInterpCubic", "SumPrint"}) {
        try {
            f.number(key);
        } catch (const std::runtime_error&) {
        }
        try {
            f.integer(key);
        } catch (const std::runtime_error&) {
        }
        try {
            f.flag(key);
        } catch (const std::runtime_error&) {
        }
        try {
            f.number_or(key, 0.0);
            f.path(key);
        } catch (const std::runtime_error&) {
        }
    }
    return 0;
}
