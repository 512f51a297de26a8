// libFuzzer target: a MAP++ input file through map::read_map_input and its
// conversion into mooring lines (analysis/map_mooring.cpp).
// Properties: no crash, no sanitizer report, no exception; a rejected file reports
// an error; accepted lines have positive lengths, stiffness and weight in water,
// and anchors at the water depth or as written.
#include "analysis/map_mooring.hpp"
#include "map/map_input.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    auto file = std::make_shared<const diag::SourceFile>(
        "fuzz.map", std::string(reinterpret_cast<const char*>(data), size));
    diag::Diagnostics diags;
    const auto input = map::read_map_input(file, diags);
    if (!input) {
        (void)diags.render();
        if (!diags.has_errors()) std::abort();
        return 0;
    }
    const auto lines = analysis::mooring_lines(*input, {320, 1025, 9.80665}, diags);
    (void)diags.render();
    if (!lines) {
        if (!diags.has_errors()) std::abort();
        return 0;
    }
    for (const auto& l : *lines) {
        if (!(l.properties.length > 0) || !(l.properties.axial_stiffness > 0) ||
            !(l.properties.weight_in_fluid > 0))
            std::abort();
    }
    return 0;
}
