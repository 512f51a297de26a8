// libFuzzer target: a wind file (formats/wind) through its reader. Properties: no
// crash, no sanitizer report; a rejected file throws std::runtime_error only; an
// accepted one has as many values in each column as times, one sample or more,
// rising times, and 2 to 9 columns.
#include "wind/wind_file.hpp"

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    yamsc::wind::Samples w;
    try {
        w = yamsc::wind::read_wind_file(in, "fuzz.wnd");
    } catch (const std::runtime_error&) {
        return 0;
    }
    if (w.time.empty() || w.columns < 2 || w.columns > yamsc::wind::max_columns) std::abort();
    for (const auto* c : {&w.speed, &w.direction, &w.vertical, &w.horizontal_shear, &w.power_law,
                          &w.linear_vertical_shear, &w.gust, &w.upflow})
        if (c->size() != w.time.size()) std::abort();
    for (std::size_t i = 1; i < w.time.size(); ++i)
        if (!(w.time[i] > w.time[i - 1])) std::abort();
    return 0;
}
